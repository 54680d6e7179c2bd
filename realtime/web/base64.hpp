#pragma once
// RFC 4648 base64 (with padding), for the belt strip's tiles inside JSON text: the page
// decodes it with the browser's atob().
#include <cstdint>
#include <span>
#include <string>

namespace cosmos {

std::string base64_encode(std::span<const std::uint8_t> bytes);

}  // namespace cosmos
