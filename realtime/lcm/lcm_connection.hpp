#pragma once
// Opens an LCM instance from a URL, or says in one line why it cannot: LCM itself only
// returns "not good" and prints its reasons, sometimes a dozen lines of them, to stderr.
#include <memory>
#include <string>

namespace lcm {
class LCM;
}

namespace cosmos {

// Throws InputError "LCM URL '<url>': <reason>" when the URL is malformed, names an unknown
// provider, a non-multicast udpm address, or LCM cannot set it up (no multicast route, ...).
//
// LCM's own messages are captured by redirecting file descriptor 2 while it starts, so call
// this at start-up, before other threads write to stderr.
std::unique_ptr<lcm::LCM> open_lcm(const std::string& url);

}  // namespace cosmos
