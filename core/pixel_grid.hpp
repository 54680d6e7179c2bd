#pragma once
// A row-major image of per-pixel values: the storage every per-pixel field of the
// pipeline uses, so that one row is contiguous (the real-time loop works row by row).
#include <cassert>
#include <cstddef>
#include <vector>

namespace cosmos {

template <class T>
class PixelGrid {
 public:
  PixelGrid() = default;
  PixelGrid(int width, int height, T fill = T{})
      : width_(width), height_(height), values_(static_cast<std::size_t>(width) * height, fill) {}

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t size() const { return values_.size(); }
  bool contains(int column, int row) const {
    return column >= 0 && row >= 0 && column < width_ && row < height_;
  }
  std::size_t index(int column, int row) const {
    assert(contains(column, row));
    return static_cast<std::size_t>(row) * width_ + column;
  }

  T& operator()(int column, int row) { return values_[index(column, row)]; }
  const T& operator()(int column, int row) const { return values_[index(column, row)]; }
  T& operator[](std::size_t i) { return values_[i]; }
  const T& operator[](std::size_t i) const { return values_[i]; }

  T* row(int r) { return values_.data() + static_cast<std::size_t>(r) * width_; }
  const T* row(int r) const { return values_.data() + static_cast<std::size_t>(r) * width_; }
  T* data() { return values_.data(); }
  const T* data() const { return values_.data(); }
  std::vector<T>& values() { return values_; }
  const std::vector<T>& values() const { return values_; }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<T> values_;
};

}  // namespace cosmos
