#include "core/surface/partial_window_kernels.hpp"

#include <Eigen/Dense>
#include <stdexcept>

#include "core/surface/window_monomials.hpp"

namespace cosmos {
namespace {

constexpr int kMinBicubicSamples = 16;

bool is_valid(const PartialWindowKernels::Mask& mask, int k) {
  return ((mask[static_cast<std::size_t>(k / 64)] >> (k % 64)) & 1u) != 0;
}

}  // namespace

PartialWindowKernels::PartialWindowKernels(int side, bool bicubic, int entries_log2)
    : side_(side), bicubic_(bicubic), entries_log2_(entries_log2) {
  if (side < 3 || side % 2 == 0 || side * side > kMaxSamples)
    throw std::invalid_argument("PartialWindowKernels: window side must be odd, 3..11");
  if (entries_log2 < 1 || entries_log2 > 20)
    throw std::invalid_argument("PartialWindowKernels: entries_log2 must be 1..20");
  const int half = side / 2;
  for (int k = 0; k < side * side; ++k) {
    const Eigen::Matrix<double, kBicubicTerms, 1> m =
        window_monomials(k % side - half, k / side - half);
    monomials_.push_back(m);
    outer_products_.push_back(m * m.transpose());
  }
  const std::size_t entries = std::size_t{1} << entries_log2_;
  const std::size_t kernel_size = 6 * static_cast<std::size_t>(side * side);
  kernel_storage_.reset(new double[entries * kernel_size]);
  entries_.reserve(entries);
  for (std::size_t e = 0; e < entries; ++e)
    entries_.push_back(
        {{}, false, false, Kernel(kernel_storage_.get() + e * kernel_size, 6, side * side)});
}

// Normal equations of the valid samples, solved for every sample's unit right side: column k
// is the fit's Taylor terms for z = 1 at sample k and 0 elsewhere. False when degenerate.
template <int Terms>
bool PartialWindowKernels::solve(const Mask& mask, double* kernel_storage) const {
  Eigen::Matrix<double, Terms, Terms> normal_matrix = Eigen::Matrix<double, Terms, Terms>::Zero();
  const int samples = side_ * side_;
  for (int k = 0; k < samples; ++k)
    if (is_valid(mask, k))
      normal_matrix +=
          outer_products_[static_cast<std::size_t>(k)].template topLeftCorner<Terms, Terms>();
  const Eigen::LDLT<Eigen::Matrix<double, Terms, Terms>> solver(normal_matrix);
  const auto diagonal = solver.vectorD();
  if (solver.info() != Eigen::Success || diagonal.minCoeff() <= 1e-9 * diagonal.maxCoeff())
    return false;
  // Every valid sample's right side at once (the invalid ones' columns stay zero). Bounded
  // size, on the stack: the real-time loop fits rows with this and allocates nothing.
  using RightSides = Eigen::Matrix<double, Terms, Eigen::Dynamic, 0, Terms, kMaxSamples>;
  RightSides right_sides = RightSides::Zero(Terms, samples);
  for (int k = 0; k < samples; ++k)
    if (is_valid(mask, k))
      right_sides.col(k) = monomials_[static_cast<std::size_t>(k)].template head<Terms>();
  // Through the first 6 rows of the inverse (fixed-size solves), then one small product.
  const Eigen::Matrix<double, Terms, Terms> inverse =
      solver.solve(Eigen::Matrix<double, Terms, Terms>::Identity());
  Eigen::Map<Eigen::Matrix<double, 6, Eigen::Dynamic>> kernel(kernel_storage, 6, samples);
  kernel.noalias() = inverse.template topRows<6>() * right_sides;
  return true;
}

const PartialWindowKernels::Kernel* PartialWindowKernels::kernel(const Mask& mask,
                                                                 int valid_count) {
  std::uint64_t hash = 0;
  for (std::uint64_t word : mask) hash = (hash ^ word) * 0x9E3779B97F4A7C15ULL;
  const std::size_t index = static_cast<std::size_t>(hash >> (64 - entries_log2_));
  Entry& entry = entries_[index];
  if (!entry.filled || entry.mask != mask) {
    entry.mask = mask;
    entry.filled = true;
    double* storage = kernel_storage_.get() + index * 6 * static_cast<std::size_t>(side_ * side_);
    entry.solvable = bicubic_ && valid_count >= kMinBicubicSamples
                         ? solve<kBicubicTerms>(mask, storage)
                         : solve<kBiquadraticTerms>(mask, storage);
  }
  return entry.solvable ? &entry.kernel : nullptr;
}

}  // namespace cosmos
