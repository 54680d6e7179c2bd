#!/usr/bin/env bash
# The cell's live web view in a real browser: a 5-part simulated cell runs paced with
# `--http 127.0.0.1:0`, headless Chromium (Debian's chromium, driven through chromium-driver's
# WebDriver) loads the page while the parts go by, and the page must list the very parts the
# cell printed, under the names the simulator's truth gives, in its pose table and on its belt
# strip; /api/status and /api/poses must agree. The screenshot is kept as
# build/web-view-check/web-view.png. Installs what it needs (apt output in the log only).
# Runs after scripts/test.sh, whose build and regression model base it uses.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${COSMOS_BUILD_DIR:-$root/build}
out_dir=$build_dir/web-view-check
mkdir -p "$out_dir"
log=$out_dir/check.log
: > "$log"
fail() { echo "check_web_view: $*" >&2; echo "check_web_view: the log is $log" >&2; exit 1; }

missing=()
for package in chromium chromium-driver python3 fonts-dejavu-core; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if ((${#missing[@]})); then
  echo "check_web_view: installing ${missing[*]} (apt output in $log)"
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
  { "${sudo_cmd[@]}" apt-get update -qq &&
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq \
      --no-install-recommends "${missing[@]}"; } >> "$log" 2>&1 || fail "apt-get install failed"
fi

cosmos=$build_dir/apps/cosmos
base=$build_dir/test-data/regression-80.cmb
[[ -x $cosmos ]] || fail "$cosmos is missing: run scripts/build.sh first"
if [[ ! -f $base ]]; then
  "$cosmos" modelbase build --catalog "$root/config/parts-regression.yaml" --views 80 \
    --out "$base" >> "$log" 2>&1 || fail "building the regression model base failed"
fi

# The cell publishes in-process (memq://) and keeps its page up after the source ends, so
# the browser can be slower than the five parts; the check stops it when done.
cat > "$out_dir/cell.yaml" <<EOF
cell:
  catalog: $root/config/parts-regression.yaml
  model_base: $base
  model_views: 80
sim_source:
  parts: 5
lcm:
  url: "memq://"
web:
  linger_s: 180
EOF

status=0
COSMOS=$cosmos OUT_DIR=$out_dir python3 - >> "$log" 2>&1 <<'PY' || status=$?
import base64, json, os, re, socket, subprocess, sys, time, urllib.request

out_dir = os.environ["OUT_DIR"]
checks = []


def check(ok, what):
    checks.append((ok, what))
    print(("ok:   " if ok else "FAIL: ") + what, flush=True)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def request(url, body=None, method=None, timeout=30):
    data = None if body is None else json.dumps(body).encode()
    req = urllib.request.Request(url, data=data, method=method or ("POST" if data else "GET"),
                                 headers={"Content-Type": "application/json"})
    with urllib.request.urlopen(req, timeout=timeout) as reply:
        return json.loads(reply.read().decode() or "null")


def wait_for(condition, seconds, what):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        value = condition()
        if value:
            return value
        time.sleep(0.2)
    raise SystemExit(f"timed out after {seconds} s waiting for {what}")


driver_port = free_port()
driver = subprocess.Popen(["chromedriver", f"--port={driver_port}",
                           f"--log-path={out_dir}/chromedriver.log"],
                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
cell_out = open(f"{out_dir}/cell.out", "w+")
cell = None
session = None
webdriver = f"http://127.0.0.1:{driver_port}"
try:
    def driver_ready():
        try:
            return request(f"{webdriver}/status", timeout=2)["value"]["ready"]
        except OSError:
            return False
    wait_for(driver_ready, 30, "chromedriver")
    options = {"binary": "/usr/bin/chromium",
               "args": ["--headless=new", "--no-sandbox", "--disable-gpu",
                        "--disable-dev-shm-usage", "--hide-scrollbars",
                        "--window-size=1400,960"]}
    session = request(f"{webdriver}/session", {"capabilities": {"alwaysMatch": {
        "browserName": "chrome", "goog:chromeOptions": options}}})["value"]["sessionId"]
    page = f"{webdriver}/session/{session}"

    def script(code):
        return request(f"{page}/execute/sync", {"script": code, "args": []})["value"]

    # The browser is up before the cell starts, so it loads the page while parts go by.
    cell = subprocess.Popen([os.environ["COSMOS"], "cell", "--config", f"{out_dir}/cell.yaml",
                             "--http", "127.0.0.1:0"], stdout=cell_out, stderr=subprocess.STDOUT)

    def cell_output():
        cell_out.flush()
        with open(f"{out_dir}/cell.out") as f:
            return f.read()

    def cell_url():
        if cell.poll() is not None:
            raise SystemExit("the cell exited: " + cell_output()[-400:])
        found = re.search(r"cell: web view at (http://\S+)", cell_output())
        return found and found.group(1)
    url = wait_for(cell_url, 60, "the cell's web view address")
    request(f"{page}/url", {"url": url})

    summary_line = r"cell: of (\d+) parts placed: (\d+) identified"
    wait_for(lambda: re.search(summary_line, cell_output()), 120, "the cell's summary")
    text = cell_output()
    printed = {}  # part_seq -> (name, truth)
    for m in re.finditer(r"^\s+(\d+)\s+(\S+)\s+(OK|REJECTED|ERROR)\s.*?truth: (\S+)\s*$", text,
                         re.MULTILINE):
        printed[int(m.group(1))] = (m.group(2), m.group(4))
    check(len(printed) == 5, f"the cell printed 5 poses ({len(printed)})")
    check(all(name == truth for name, truth in printed.values()),
          "the cell named every part as the simulator's truth: " +
          ", ".join(f"{n} ({t})" for n, t in printed.values()))

    table_js = ("return [...document.querySelectorAll('#poses tbody tr')]"
                ".map(r => [Number(r.cells[0].textContent), r.cells[1].textContent]);")
    wait_for(lambda: len(script(table_js)) >= len(printed), 30, "the page's pose table")
    shown = {seq: name for seq, name in script(table_js)}
    check(shown == {seq: name for seq, (name, _) in printed.items()},
          f"the page's pose table lists the cell's parts by name: {shown}")
    labels_js = ("return [...document.querySelectorAll('#strip-labels .strip-label')]"
                 ".map(l => l.textContent);")
    labels = sorted(script(labels_js))
    check(labels == sorted(name for name, _ in printed.values()),
          f"the belt strip labels every part: {labels}")
    state = script("return document.getElementById('state').textContent;")
    counters = script("return [...document.querySelectorAll('#counters tr')].map(r => "
                      "[r.cells[0].textContent, r.cells[1].textContent]);")
    check(state == "IDLE" and ["parts_seen", "5"] in counters,
          f"the page shows the ended run's status (state {state}, counters {counters[:3]}...)")

    status = request(url + "api/status")
    poses = request(url + "api/poses")["poses"]
    check(status["status"]["parts_seen"] == 5 and status["pose_latency_ms"]["count"] == 5,
          "/api/status counts the 5 parts and their latencies")
    check(sorted((p["part_seq"], p["part_name"]) for p in poses) ==
          sorted((seq, name) for seq, (name, _) in printed.items()),
          "/api/poses lists the cell's poses")

    time.sleep(0.5)  # the strip's next redraw
    screenshot = request(f"{page}/screenshot")["value"]
    with open(f"{out_dir}/web-view.png", "wb") as f:
        f.write(base64.b64decode(screenshot))
    print(f"screenshot: {out_dir}/web-view.png")
finally:
    if session:
        try:
            request(f"{webdriver}/session/{session}", method="DELETE")
        except OSError:
            pass
    for process in (cell, driver):
        if process and process.poll() is None:
            process.terminate()
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()

failed = sum(not ok for ok, _ in checks)
print(f"check_web_view: {len(checks) - failed} passed, {failed} failed")
sys.exit(1 if failed or not checks else 0)
PY
grep "^FAIL\|^ok" "$log" | sed 's/^/check_web_view: /' || true
((status == 0)) || fail "$(tail -n 3 "$log")"
tail -n 1 "$log"
