#pragma once
// One line of a HIL check's verdict, as the guest prints it: "hil: PASS …", "hil: FAIL …" or
// "hil: INFO …" (a measured fact that decides nothing). scripts/hil.sh shows these lines.
#include <cstdio>
#include <string>
#include <vector>

namespace cosmos::hil {

struct ProbeCheck {
  bool ok = false;
  std::string line;
  bool info = false;  // a measured fact, not a pass/fail check
};

template <class... Values>
ProbeCheck check_line(bool ok, const char* format, Values... values) {
  char line[1024];
  std::snprintf(line, sizeof line, format, values...);
  return {ok, line, false};
}

template <class... Values>
ProbeCheck info_line(const char* format, Values... values) {
  ProbeCheck check = check_line(true, format, values...);
  check.info = true;
  return check;
}

// Prints every line; the number of failed checks.
inline int print_checks(const std::vector<ProbeCheck>& checks) {
  int failed = 0;
  for (const ProbeCheck& check : checks) {
    std::printf("hil: %s %s\n",
                check.info ? "INFO"
                : check.ok ? "PASS"
                           : "FAIL",
                check.line.c_str());
    failed += check.ok ? 0 : 1;
  }
  std::fflush(stdout);
  return failed;
}

}  // namespace cosmos::hil
