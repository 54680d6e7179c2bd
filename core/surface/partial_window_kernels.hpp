#pragma once
// The least-squares window fit of §3.5.1 where some samples are missing or lie across a depth
// jump: once it is known which samples are valid, the fit is linear in them, so one kernel
// per validity pattern (6 x window samples) gives the quadric Taylor terms at the centre.
// Silhouettes, borders and holes repeat few patterns, so kernels are kept in a fixed
// direct-mapped table: nothing is allocated after construction, and a result never depends
// on what happened to be cached (a kernel is a function of its pattern alone).
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace cosmos {

class PartialWindowKernels {
 public:
  static constexpr int kMaxSamples = 128;
  using Mask = std::array<std::uint64_t, kMaxSamples / 64>;  // bit k: sample k valid
  using Kernel = Eigen::Map<const Eigen::Matrix<double, 6, Eigen::Dynamic>>;

  // The table of one image's fit: 2048 kernels (2.4 MB for 5 x 5 windows). The silhouettes,
  // borders and holes of a catalog scan repeat more validity patterns than a smaller table
  // keeps, and every miss solves a least-squares system.
  static constexpr int kImageEntriesLog2 = 11;
  // A table kept over a stream of images (a model base's views): their patterns outnumber one
  // image's several times, and a table of one image's size would evict most of them before
  // the next view repeats them.
  static constexpr int kStreamEntriesLog2 = 14;

  // side x side windows (side <= 11), row-major samples with u fastest; the bicubic needs 16
  // valid samples, below that the biquadratic is fitted. 2^entries_log2 entries, direct
  // mapped; their storage costs nothing until an entry is filled.
  PartialWindowKernels(int side, bool bicubic, int entries_log2 = kImageEntriesLog2);

  // The kernel of `mask` (its `valid_count` set bits), zero in the columns of invalid
  // samples; nullptr when the valid samples do not determine the surface (e.g. on one line).
  const Kernel* kernel(const Mask& mask, int valid_count);

  int side() const { return side_; }
  bool bicubic() const { return bicubic_; }

 private:
  struct Entry {
    Mask mask{};
    bool filled = false;
    bool solvable = false;
    Kernel kernel;  // into kernel_storage_
  };
  template <int Terms>
  bool solve(const Mask& mask, double* kernel) const;

  int side_;
  bool bicubic_;
  int entries_log2_;
  std::vector<Eigen::Matrix<double, 10, 1>> monomials_;        // per sample
  std::vector<Eigen::Matrix<double, 10, 10>> outer_products_;  // per sample, m m^T
  std::vector<Entry> entries_;
  // Every entry's kernel, uninitialized: a fitter touches only the entries it fills, so a
  // large table costs nothing until used.
  std::unique_ptr<double[]> kernel_storage_;
};

}  // namespace cosmos
