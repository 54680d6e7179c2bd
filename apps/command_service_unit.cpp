// `cosmos service-unit --config FILE [--unit-config PATH] [--fetch-catalog PATH] [--exec PATH]`:
// prints the systemd unit that runs the cell as a service, cosmos-cell.service. Its limits come
// from the config's realtime: section, so the service may apply what the cell asks for: LimitRTPRIO
// for realtime.sched_fifo_priority, LimitMEMLOCK for realtime.lock_memory, and for realtime.cpu a
// CPUAffinity of every other CPU, so the recognizer and publisher threads keep off the CPU the
// acquisition thread pins itself to (a thread may pin itself outside its process's affinity).
// The package ships the unit printed for its config; after editing /etc/cosmos-cell/cell.yaml,
// print it again into /etc/systemd/system/.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "apps/command_registry.hpp"
#include "realtime/config/cell_config.hpp"

namespace cosmos::cli {
namespace {

namespace fs = std::filesystem;

constexpr char kStateDir[] = "/var/lib/cosmos-cell";  // systemd's StateDirectory=cosmos-cell

struct ServiceUnitOptions {
  std::string config;
  std::string unit_config;    // the config path the unit names (default: --config, absolute)
  std::string fetch_catalog;  // the catalog fetch run before the cell (default: the installed one)
  std::string exec;           // the `cosmos` the unit starts (default: this one)
};

// Every online CPU but `cpu`, as systemd lists them ("0 1 3"); `cpu` alone on a one-CPU machine.
std::string other_cpus(int cpu) {
  const long count = ::sysconf(_SC_NPROCESSORS_ONLN);
  std::string list;
  for (long other = 0; other < count; ++other)
    if (other != cpu) list += (list.empty() ? "" : " ") + std::to_string(other);
  return list.empty() ? std::to_string(cpu) : list;
}

// The fetch script installed beside the binary (<prefix>/libexec/cosmos-cell/), when there is one.
std::string installed_fetch_catalog() {
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  if (error) return "";
  const fs::path script =
      exe.parent_path().parent_path() / "libexec" / "cosmos-cell" / "fetch_catalog.sh";
  return fs::exists(script, error) ? script.string() : "";
}

void run_service_unit(const ServiceUnitOptions& options) {
  const CellConfig config = load_cell_config(options.config);
  const RealtimeSettings& rt = config.realtime.threads.thread;
  const std::string unit_config =
      options.unit_config.empty() ? fs::absolute(options.config).string() : options.unit_config;
  std::error_code error;
  const std::string exe =
      options.exec.empty() ? fs::read_symlink("/proc/self/exe", error).string() : options.exec;
  const std::string fetch =
      options.fetch_catalog.empty() ? installed_fetch_catalog() : options.fetch_catalog;

  std::printf(
      "# cosmos-cell.service, printed by `cosmos service-unit --config %s` from its realtime:\n"
      "# section. After editing that section, print it again into\n"
      "# /etc/systemd/system/cosmos-cell.service and run `systemctl daemon-reload`.\n"
      "[Unit]\n"
      "Description=COSMOS-Cell: 3D part recognition on a laser-line scanner work cell\n"
      "After=network-online.target\n"
      "Wants=network-online.target\n"
      "\n"
      "[Service]\n"
      "Type=simple\n"
      "# The meshes and the cached model base live here ($COSMOS_CACHE_DIR).\n"
      "StateDirectory=cosmos-cell\n"
      "WorkingDirectory=%s\n"
      "Environment=COSMOS_CACHE_DIR=%s\n"
      "# COSMOS_CELL_ARGS: more arguments of `cosmos cell`, e.g.\n"
      "# COSMOS_CELL_ARGS=--source hardware --hardware /etc/cosmos-cell/hardware-example.yaml\n"
      "EnvironmentFile=-/etc/default/cosmos-cell\n",
      unit_config.c_str(), kStateDir, kStateDir);
  if (!fetch.empty()) std::printf("ExecStartPre=%s\n", fetch.c_str());
  std::printf(
      "ExecStart=%s cell --config %s $COSMOS_CELL_ARGS\n"
      "Restart=on-failure\n"
      "RestartSec=5\n",
      error ? "/usr/bin/cosmos" : exe.c_str(), unit_config.c_str());
  std::printf("# realtime.sched_fifo_priority: %d\n", rt.sched_fifo_priority);
  std::printf("LimitRTPRIO=%d\n", rt.sched_fifo_priority);
  std::printf("# realtime.lock_memory: %s\n", rt.lock_memory ? "true" : "false");
  if (rt.lock_memory) std::printf("LimitMEMLOCK=infinity\n");
  std::printf("# realtime.cpu: %d%s\n", rt.cpu, rt.cpu < 0 ? " (no CPU is reserved)" : "");
  if (rt.cpu >= 0) std::printf("CPUAffinity=%s\n", other_cpus(rt.cpu).c_str());
  std::printf(
      "\n"
      "[Install]\n"
      "WantedBy=multi-user.target\n");
}

void install_service_unit(CLI::App& root) {
  auto options = std::make_shared<ServiceUnitOptions>();
  CLI::App* command = root.add_subcommand(
      "service-unit", "Print the systemd unit that runs the cell with this config as a service");
  command->add_option("--config", options->config, "the cell configuration")
      ->type_name("FILE")
      ->required();
  command
      ->add_option("--unit-config", options->unit_config,
                   "the config path the unit runs with (default: --config)")
      ->type_name("PATH");
  command
      ->add_option("--fetch-catalog", options->fetch_catalog,
                   "the catalog fetch run before the cell (default: the installed one)")
      ->type_name("PATH");
  command
      ->add_option("--exec", options->exec, "the cosmos binary the unit starts (default: this one)")
      ->type_name("PATH");
  command->callback([options] { run_service_unit(*options); });
}

const CommandRegistration registration{"service-unit", install_service_unit};

}  // namespace
}  // namespace cosmos::cli
