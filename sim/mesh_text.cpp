#include "sim/mesh_text.hpp"

#include <charconv>
#include <cstring>
#include <fstream>
#include <iterator>
#include <system_error>

#include "core/input_error.hpp"

namespace cosmos {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }

template <typename Value>
std::optional<Value> parse_whole(std::string_view token) {
  if (token.size() > 1 && token.front() == '+' && token[1] != '-') token.remove_prefix(1);
  Value value{};
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value);
  if (error != std::errc{} || stop != end || token.empty()) return std::nullopt;
  return value;
}

}  // namespace

MeshText::MeshText(const std::filesystem::path& path) : path_(path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) fail_in_file("cannot open the mesh file");
  bytes_.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

bool MeshText::at_line_break() const {
  return at_ < bytes_.size() && (bytes_[at_] == '\n' || bytes_[at_] == '\r');
}

void MeshText::skip_blanks() {
  while (at_ < bytes_.size() && is_blank(bytes_[at_])) ++at_;
}

void MeshText::skip_line() {
  while (at_ < bytes_.size() && !at_line_break()) ++at_;
  if (at_ >= bytes_.size()) return;
  if (bytes_[at_] == '\r' && at_ + 1 < bytes_.size() && bytes_[at_ + 1] == '\n') ++at_;
  ++at_;
  ++line_;
}

bool MeshText::next_data_line(bool hash_comments) {
  for (;;) {
    skip_blanks();
    if (at_ >= bytes_.size()) return false;
    if (!at_line_break() && !(hash_comments && bytes_[at_] == '#')) return true;
    skip_line();
  }
}

std::string_view MeshText::token_on_line(bool hash_comments) {
  skip_blanks();
  if (at_ >= bytes_.size() || at_line_break() || (hash_comments && bytes_[at_] == '#')) return {};
  const std::size_t start = at_;
  while (at_ < bytes_.size() && !is_blank(bytes_[at_]) && !at_line_break() &&
         !(hash_comments && bytes_[at_] == '#'))
    ++at_;
  return std::string_view(bytes_).substr(start, at_ - start);
}

std::string_view MeshText::token() {
  return next_data_line(false) ? token_on_line(false) : std::string_view{};
}

void MeshText::fail(const std::string& reason) const { fail_at(line_, reason); }

void MeshText::fail_at(std::size_t line, const std::string& reason) const {
  throw InputError(path_.string() + ":" + std::to_string(line) + ": " + reason);
}

void MeshText::fail_in_file(const std::string& reason) const {
  throw InputError(path_.string() + ": " + reason);
}

std::string quoted(std::string_view token) {
  constexpr std::size_t kShown = 40;
  std::string text = "'";
  for (std::size_t k = 0; k < token.size() && k < kShown; ++k) {
    const auto byte = static_cast<unsigned char>(token[k]);
    if (byte >= 0x20 && byte < 0x7f) {
      text.push_back(static_cast<char>(byte));
    } else {
      constexpr const char* kHex = "0123456789abcdef";
      text.append("\\x").push_back(kHex[byte >> 4]);
      text.push_back(kHex[byte & 0xf]);
    }
  }
  return text.append(token.size() > kShown ? "...'" : "'");
}

std::optional<double> parse_number(std::string_view token) { return parse_whole<double>(token); }

std::optional<long long> parse_integer(std::string_view token) {
  return parse_whole<long long>(token);
}

std::uint64_t unsigned_at(std::string_view bytes, std::size_t at, std::size_t size,
                          bool big_endian) {
  std::uint64_t bits = 0;
  for (std::size_t k = 0; k < size; ++k) {
    const auto byte = static_cast<unsigned char>(bytes[at + k]);
    bits |= static_cast<std::uint64_t>(byte) << (8 * (big_endian ? size - 1 - k : k));
  }
  return bits;
}

float float_of_bits(std::uint32_t bits) {
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace cosmos
