#pragma once
// The one-line reason a hardware step failed ("/dev/video0: VIDIOC_S_FMT: pixel format Y16 not
// supported"), kept in a fixed buffer inside the adapter. Hardware errors can happen on the
// acquisition thread (a failed DQBUF, a vanished GPIO chip), where nothing may allocate or
// throw, so the text is formatted with vsnprintf into storage owned by the adapter and read
// back as a string_view. Longer messages are truncated, never reallocated.
#include <algorithm>
#include <array>
#include <cstdarg>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <string_view>

namespace cosmos {

class ErrorLine {
 public:
  static constexpr std::size_t kCapacity = 256;

  [[gnu::format(printf, 2, 3)]] void set(const char* format, ...) noexcept {
    va_list arguments;
    va_start(arguments, format);
    const int written = std::vsnprintf(text_.data(), text_.size(), format, arguments);
    va_end(arguments);
    size_ =
        written < 0 ? 0 : std::min<std::size_t>(static_cast<std::size_t>(written), kCapacity - 1);
  }

  void clear() noexcept {
    text_[0] = '\0';
    size_ = 0;
  }

  bool empty() const noexcept { return size_ == 0; }
  std::string_view view() const noexcept { return {text_.data(), size_}; }
  const char* c_str() const noexcept { return text_.data(); }

 private:
  std::array<char, kCapacity> text_{};
  std::size_t size_ = 0;
};

// errno → its description without touching the locale machinery or a shared buffer:
// strerror() may format unknown numbers into static storage, which is not thread-safe.
inline const char* errno_text(int error_number) noexcept {
  const char* text = strerrordesc_np(error_number);
  return text != nullptr ? text : "unknown error";
}

}  // namespace cosmos
