#include "core/partial_window_kernels.hpp"

#include <Eigen/Dense>
#include <stdexcept>

#include "core/window_monomials.hpp"

namespace cosmos {
namespace {

constexpr int kMinBicubicSamples = 16;
constexpr int kEntriesLog2 = 8;

bool is_valid(const PartialWindowKernels::Mask& mask, int k) {
  return ((mask[static_cast<std::size_t>(k / 64)] >> (k % 64)) & 1u) != 0;
}

}  // namespace

PartialWindowKernels::PartialWindowKernels(int side, bool bicubic)
    : side_(side), bicubic_(bicubic), entries_(std::size_t{1} << kEntriesLog2) {
  if (side < 3 || side % 2 == 0 || side * side > kMaxSamples)
    throw std::invalid_argument("PartialWindowKernels: window side must be odd, 3..11");
  const int half = side / 2;
  for (int k = 0; k < side * side; ++k) {
    const Eigen::Matrix<double, kBicubicTerms, 1> m = window_monomials(k % side - half, k / side - half);
    monomials_.push_back(m);
    outer_products_.push_back(m * m.transpose());
  }
  for (Entry& entry : entries_) entry.kernel = Kernel::Zero(6, side * side);
}

// Normal equations of the valid samples, solved for every sample's unit right side: column k
// is the fit's Taylor terms for z = 1 at sample k and 0 elsewhere. False when degenerate.
template <int Terms>
bool PartialWindowKernels::solve(const Mask& mask, Kernel& kernel) const {
  Eigen::Matrix<double, Terms, Terms> normal_matrix = Eigen::Matrix<double, Terms, Terms>::Zero();
  const int samples = side_ * side_;
  for (int k = 0; k < samples; ++k)
    if (is_valid(mask, k))
      normal_matrix += outer_products_[static_cast<std::size_t>(k)].template topLeftCorner<Terms, Terms>();
  const Eigen::LDLT<Eigen::Matrix<double, Terms, Terms>> solver(normal_matrix);
  const auto diagonal = solver.vectorD();
  if (solver.info() != Eigen::Success || diagonal.minCoeff() <= 1e-9 * diagonal.maxCoeff())
    return false;
  // Every valid sample's right side at once (the invalid ones' columns stay zero): one
  // triangular solve over a matrix instead of one per sample. Bounded size, on the stack: the
  // real-time loop fits rows with this and allocates nothing.
  using RightSides = Eigen::Matrix<double, Terms, Eigen::Dynamic, 0, Terms, kMaxSamples>;
  RightSides right_sides = RightSides::Zero(Terms, samples);
  for (int k = 0; k < samples; ++k)
    if (is_valid(mask, k))
      right_sides.col(k) = monomials_[static_cast<std::size_t>(k)].template head<Terms>();
  solver.solveInPlace(right_sides);
  kernel = right_sides.template topRows<6>();
  return true;
}

const PartialWindowKernels::Kernel* PartialWindowKernels::kernel(const Mask& mask, int valid_count) {
  std::uint64_t hash = 0;
  for (std::uint64_t word : mask) hash = (hash ^ word) * 0x9E3779B97F4A7C15ULL;
  Entry& entry = entries_[static_cast<std::size_t>(hash >> (64 - kEntriesLog2))];
  if (!entry.filled || entry.mask != mask) {
    entry.mask = mask;
    entry.filled = true;
    entry.solvable = bicubic_ && valid_count >= kMinBicubicSamples
                         ? solve<kBicubicTerms>(mask, entry.kernel)
                         : solve<kBiquadraticTerms>(mask, entry.kernel);
  }
  return entry.solvable ? &entry.kernel : nullptr;
}

}  // namespace cosmos
