#include "realtime/lcm/lcm_connection.hpp"

#include <arpa/inet.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <sstream>

#include "core/input_error.hpp"

namespace cosmos {
namespace {

// Collects what is written to stderr (fd 2) between construction and finish().
class StderrCapture {
 public:
  StderrCapture() {
    std::fflush(stderr);
    file_ = std::tmpfile();
    if (file_ == nullptr) return;
    saved_fd_ = ::dup(STDERR_FILENO);
    if (saved_fd_ < 0 || ::dup2(::fileno(file_), STDERR_FILENO) < 0) restore();
  }
  ~StderrCapture() { finish(); }
  StderrCapture(const StderrCapture&) = delete;
  StderrCapture& operator=(const StderrCapture&) = delete;

  std::string finish() {
    std::string text;
    if (file_ == nullptr) return text;
    restore();
    std::rewind(file_);
    char chunk[512];
    std::size_t read = 0;
    while ((read = std::fread(chunk, 1, sizeof chunk, file_)) > 0) text.append(chunk, read);
    std::fclose(file_);
    file_ = nullptr;
    return text;
  }

 private:
  void restore() {
    if (saved_fd_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_fd_, STDERR_FILENO);
    ::close(saved_fd_);
    saved_fd_ = -1;
  }

  std::FILE* file_ = nullptr;
  int saved_fd_ = -1;
};

// LCM's udpm provider reports a unicast address only as a failed IP_ADD_MEMBERSHIP.
std::string udpm_address_problem(const std::string& url) {
  const std::string prefix = "udpm://";
  if (url.rfind(prefix, 0) != 0) return {};
  const std::string rest = url.substr(prefix.size());
  const std::string host = rest.substr(0, rest.find_first_of(":?"));
  in_addr address{};
  if (host.empty() || ::inet_pton(AF_INET, host.c_str(), &address) != 1) return {};  // LCM says it
  const unsigned first_octet = ntohl(address.s_addr) >> 24;
  if (first_octet >= 224 && first_octet <= 239) return {};
  return host + " is not a multicast group address (224.0.0.0 to 239.255.255.255)";
}

// One line out of LCM's diagnostics.
std::string reason_from(const std::string& diagnostics) {
  if (diagnostics.find("multicast route") != std::string::npos) {
    return "no route to the multicast group (on a machine without network: "
           "ip link set lo up && ip route add 224.0.0.0/4 dev lo)";
  }
  std::istringstream lines(diagnostics);
  std::string line;
  while (std::getline(lines, line)) {
    const auto begin = line.find_first_not_of(" \t\r");
    if (begin == std::string::npos) continue;
    line = line.substr(begin);
    const std::string error_prefix = "Error: ";
    if (line.rfind(error_prefix, 0) == 0) line = line.substr(error_prefix.size());
    return line;
  }
  return "LCM could not open it";
}

}  // namespace

std::unique_ptr<lcm::LCM> open_lcm(const std::string& url) {
  const std::string where = "LCM URL '" + url + "': ";
  if (url.find("://") == std::string::npos) {
    throw InputError(where +
                     "not of the form provider://address?options (e.g. "
                     "udpm://239.255.76.67:7667?ttl=0, memq://)");
  }
  if (const std::string problem = udpm_address_problem(url); !problem.empty())
    throw InputError(where + problem);

  StderrCapture capture;
  auto lcm = std::make_unique<lcm::LCM>(url);
  const std::string diagnostics = capture.finish();
  if (!lcm->good()) throw InputError(where + reason_from(diagnostics));
  // A working instance's warnings are still worth seeing.
  if (!diagnostics.empty()) std::cerr << diagnostics << std::flush;
  return lcm;
}

}  // namespace cosmos
