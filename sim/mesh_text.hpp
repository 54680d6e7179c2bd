#pragma once
// A mesh file's bytes read as text, token by token, with the line each token is on: the one
// tokenizer of the OFF, OBJ and ASCII STL readers and of the PLY reader's header and ASCII body
// (sim/off_mesh_reader.hpp, sim/obj_mesh_reader.hpp, sim/stl_mesh_reader.hpp,
// sim/ply_mesh_reader.hpp), and the decoding of their binary bodies. A line ends at "\n",
// "\r\n" or a lone "\r" (old Mac files), the same for every caller, so a line count in an error
// is the line an editor shows. Every refusal is one InputError line "FILE:LINE: reason".
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace cosmos {

class MeshText {
 public:
  // Reads the whole file (InputError naming it when it cannot be opened).
  explicit MeshText(const std::filesystem::path& path);

  // Moves to the next line holding a token, past blank lines and, when `hash_comments` is
  // set, past everything from a '#' to the line's end. False at the end of the file.
  bool next_data_line(bool hash_comments);
  // The next token of the current line ('#' starts a comment when `hash_comments` is set);
  // empty at the line's end.
  std::string_view token_on_line(bool hash_comments);
  // The next token on this line or a later one; empty at the end of the file.
  std::string_view token();
  // Moves past the current line's end.
  void skip_line();

  // The 1-based line the cursor is on.
  std::size_t line() const { return line_; }
  std::size_t offset() const { return at_; }
  const std::string& bytes() const { return bytes_; }
  std::size_t bytes_after_cursor() const { return bytes_.size() - at_; }
  const std::filesystem::path& path() const { return path_; }

  // InputError "FILE:LINE: reason" at the cursor's line, or at an earlier line.
  [[noreturn]] void fail(const std::string& reason) const;
  [[noreturn]] void fail_at(std::size_t line, const std::string& reason) const;
  // InputError "FILE: reason", for what no line holds (a binary body).
  [[noreturn]] void fail_in_file(const std::string& reason) const;

 private:
  bool at_line_break() const;
  void skip_blanks();

  std::filesystem::path path_;
  std::string bytes_;
  std::size_t at_ = 0;
  std::size_t line_ = 1;
};

// The token in single quotes, as a message shows it: bytes outside printable ASCII as \xHH (a
// binary file read as text holds NULs and control bytes a terminal would act on), and past 40
// characters cut with "...", since a token of binary data can be the whole file.
std::string quoted(std::string_view token);

// A whole token as a number (std::from_chars: no locale; "inf" and "nan" are numbers, a
// leading '+' is accepted), or nothing.
std::optional<double> parse_number(std::string_view token);
// A whole token as an integer, or nothing.
std::optional<long long> parse_integer(std::string_view token);

// The `size` bytes (1 to 8) at `at` as an unsigned integer stored least significant byte
// first, or most significant first when `big_endian`: a binary body's scalars, decoded the
// same on any host. The caller checks that the bytes are there.
std::uint64_t unsigned_at(std::string_view bytes, std::size_t at, std::size_t size,
                          bool big_endian = false);
// The IEEE 754 single whose bits these are.
float float_of_bits(std::uint32_t bits);

}  // namespace cosmos
