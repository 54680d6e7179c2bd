#pragma once
// The page's files (realtime/web/assets/), embedded into the binary at build time
// (embed_web_assets.cmake), so the cell serves its view with nothing installed beside it and
// the browser loads nothing from elsewhere.
#include <cstddef>
#include <span>
#include <string_view>

namespace cosmos {

struct WebAsset {
  std::string_view path;          // "/index.html", "/app.js", ...
  std::string_view content_type;  // "text/html; charset=utf-8", ...
  std::string_view content;
};

std::span<const WebAsset> web_assets();
// nullptr when there is no such file; "/" is "/index.html".
const WebAsset* find_web_asset(std::string_view path);

}  // namespace cosmos
