// The page embedded in the binary: every file of realtime/web/assets/ served under its name,
// "/" the index, the index loading only the page's own files, and nothing loaded from
// another host (the cell's network has no internet, and its view must not need any).
#include "realtime/web/web_assets.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace cosmos {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(WebAssets, EmbedsEveryFileOfTheAssetsFolderByteForByte) {
  const fs::path folder = fs::path(COSMOS_SOURCE_DIR) / "realtime/web/assets";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    std::string path = "/";  // appended: GCC 12 warns (-Wrestrict) about "/" + name
    path.append(entry.path().filename().string());
    const WebAsset* asset = find_web_asset(path);
    ASSERT_NE(asset, nullptr) << path;
    EXPECT_EQ(asset->content, read_text(entry.path())) << path;
    ++files;
  }
  EXPECT_EQ(static_cast<std::size_t>(files), web_assets().size());
  EXPECT_GE(files, 3);
}

TEST(WebAssets, ServesTheIndexAtTheRootWithItsContentTypes) {
  const WebAsset* index = find_web_asset("/");
  ASSERT_NE(index, nullptr);
  EXPECT_EQ(index->path, "/index.html");
  EXPECT_EQ(index->content_type, "text/html; charset=utf-8");
  ASSERT_NE(find_web_asset("/app.js"), nullptr);
  EXPECT_EQ(find_web_asset("/app.js")->content_type, "text/javascript; charset=utf-8");
  EXPECT_EQ(find_web_asset("/style.css")->content_type, "text/css; charset=utf-8");
  EXPECT_EQ(find_web_asset("/missing.js"), nullptr);
  EXPECT_EQ(find_web_asset("index.html"), nullptr);
}

TEST(WebAssets, TheIndexLoadsThePagesOwnFilesAndNothingFromElsewhere) {
  const std::string index(find_web_asset("/")->content);
  EXPECT_NE(index.find("src=\"/app.js\""), std::string::npos);
  EXPECT_NE(index.find("href=\"/style.css\""), std::string::npos);
  for (const WebAsset& asset : web_assets()) {
    const std::string text(asset.content);
    EXPECT_EQ(text.find("http://"), std::string::npos) << asset.path;
    EXPECT_EQ(text.find("https://"), std::string::npos) << asset.path;
    EXPECT_EQ(text.find("\"//"), std::string::npos) << asset.path;
  }
}

}  // namespace
}  // namespace cosmos
