#include "core/registration/packed_registration_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/registration/occupied_cell_runs.hpp"
#include "core/registration/rice_bit_stream.hpp"

namespace cosmos {
namespace {

constexpr int kChannels = kSurfaceCoefficients;
// The derivative of each coefficient along x and y, and d(coefficient)/d(derivative):
// h_x = a, h_y = b; a_x = 2 c_xx, a_y = c_xy; b_x = c_xy, b_y = 2 c_yy.
struct Derivative {
  int along_x = -1, along_y = -1;
  double factor_x = 0, factor_y = 0;
};
constexpr Derivative kDerivatives[kChannels] = {
    {kSlopeX, kSlopeY, 1, 1}, {kCurveXX, kCurveXY, 2, 1}, {kCurveXY, kCurveYY, 1, 2}, {}, {}, {}};
// Every integer and every prediction stays within +-2^28, so a residual fits a 32-bit code.
constexpr std::int32_t kMaxUnits = std::int32_t{1} << 28;
constexpr std::int32_t kMaxDerivativeRatio = std::int32_t{1} << 30;
// A coefficient the noise does not reach (sigma 0: unused by the plane fit, or a cofactor
// that says nothing) is kept to this fraction of its largest magnitude in the view.
constexpr double kUnitsPerMagnitude = 1 << 20;

using Units = std::array<std::int32_t, kChannels>;

// The integers of the cells left, above and above-left of a point (null: not a point).
struct Neighbours {
  const Units* left = nullptr;
  const Units* up = nullptr;
  const Units* up_left = nullptr;
};

std::int64_t clamp_units(std::int64_t value, const CoefficientCoding& coding) {
  return std::clamp<std::int64_t>(value, coding.low, coding.high);
}

// The one prediction every reader computes alike (integers only), within [low, high].
// Inlined: unpacking runs it for every coefficient of every point.
[[gnu::always_inline]] inline std::int64_t predict(const PackedRegistrationPoints& packed,
                                                   int channel, const Neighbours& n,
                                                   const Units& current) {
  const CoefficientCoding& coding = packed.coefficients[static_cast<std::size_t>(channel)];
  const auto c = static_cast<std::size_t>(channel);
  std::int64_t prediction = 0;
  const auto predictor = static_cast<CoefficientPredictor>(coding.predictor);
  const Derivative& derivative = kDerivatives[c];
  if (predictor == CoefficientPredictor::kDerivativeTrapezoid && derivative.along_x >= 0) {
    const auto along = [&](const Units& from, int d, std::int32_t ratio) {
      const auto k = static_cast<std::size_t>(d);
      const std::int64_t derivatives = std::int64_t{from[k]} + current[k];
      return from[c] + ((derivatives * ratio + kDerivativeRatioOne / 2) >> 16);
    };
    if (n.left && n.up)
      prediction = (along(*n.left, derivative.along_x, coding.ratio_x) +
                    along(*n.up, derivative.along_y, coding.ratio_y)) >>
                   1;
    else if (n.left)
      prediction = along(*n.left, derivative.along_x, coding.ratio_x);
    else if (n.up)
      prediction = along(*n.up, derivative.along_y, coding.ratio_y);
  } else if (predictor == CoefficientPredictor::kMean && n.left && n.up) {
    prediction = (std::int64_t{(*n.left)[c]} + (*n.up)[c]) >> 1;
  } else if (n.left && n.up && n.up_left) {
    prediction = std::int64_t{(*n.left)[c]} + (*n.up)[c] - (*n.up_left)[c];
  } else if (n.left) {
    prediction = (*n.left)[c];
  } else if (n.up) {
    prediction = (*n.up)[c];
  }
  return clamp_units(prediction, coding);
}

// Cell (u, v) of a grid `grid_width` wide holds the point whose neighbours these are.
[[gnu::always_inline]] inline Neighbours neighbours_of(const std::vector<std::int32_t>& cell_point,
                                                       const std::vector<Units>& units,
                                                       int grid_width, std::size_t cell,
                                                       std::size_t u, std::size_t v) {
  Neighbours n;
  const auto at = [&](std::size_t other) -> const Units* {
    const std::int32_t point = cell_point[other];
    return point >= 0 ? &units[static_cast<std::size_t>(point)] : nullptr;
  };
  const auto width = static_cast<std::size_t>(grid_width);
  if (u > 0) n.left = at(cell - 1);
  if (v > 0) n.up = at(cell - width);
  if (u > 0 && v > 0) n.up_left = at(cell - width - 1);
  return n;
}

double coefficient_step(const RegistrationPoints& points, int channel) {
  const double noise_mm = std::max(points.z_noise_sigma_mm, kMinNoiseSigmaMm);
  const double cofactor = points.fit_cofactor(channel, channel);
  if (std::isfinite(cofactor) && cofactor > 0)
    return kStepPerSigma * noise_mm * std::sqrt(cofactor);
  double largest = 0;
  for (int i = 0; i < points.size(); ++i)
    if (std::isfinite(points.surface(channel, i)))
      largest = std::max(largest, std::abs(points.surface(channel, i)));
  return largest / kUnitsPerMagnitude;
}

std::int32_t quantize(double value, double step) {
  if (!(step > 0) || !std::isfinite(value)) return 0;
  return static_cast<std::int32_t>(
      std::clamp(std::round(value / step), -double{kMaxUnits}, double{kMaxUnits}));
}

std::int32_t derivative_ratio(double factor, double spacing_mm, double derivative_step,
                              double step) {
  if (!(step > 0)) return 0;
  const double ratio =
      std::round(factor * spacing_mm * derivative_step / step / 2 * kDerivativeRatioOne);
  return static_cast<std::int32_t>(
      std::clamp(ratio, -double{kMaxDerivativeRatio}, double{kMaxDerivativeRatio}));
}

// The Rice parameter that codes these residuals in the fewest bits, and that count.
std::pair<int, std::uint64_t> best_rice_bits(const std::vector<std::uint32_t>& zigzagged) {
  std::pair<int, std::uint64_t> best{0, std::numeric_limits<std::uint64_t>::max()};
  for (int k = 0; k <= kMaxRiceBits; ++k) {
    std::uint64_t bits = 0;
    for (std::uint32_t z : zigzagged) bits += static_cast<std::uint64_t>(rice_code_bits(z, k));
    if (bits < best.second) best = {k, bits};
  }
  return best;
}

std::size_t grid_cells(const PackedRegistrationPoints& packed) {
  return static_cast<std::size_t>(std::max(packed.grid_width, 0)) *
         static_cast<std::size_t>(std::max(packed.grid_height, 0));
}

std::size_t point_count(const PackedRegistrationPoints& packed) {
  return static_cast<std::size_t>(std::max(packed.point_count, 0));
}

struct PackedStreams {
  std::vector<std::uint8_t> occupancy_runs;
  std::vector<std::uint8_t> coefficient_bits;
};

}  // namespace

PackedRegistrationPoints pack_registration_points(const RegistrationPoints& points) {
  PackedRegistrationPoints packed;
  packed.grid_width = points.grid_width;
  packed.grid_height = points.grid_height;
  packed.origin_x_mm = points.origin_x_mm;
  packed.origin_y_mm = points.origin_y_mm;
  packed.spacing_x_mm = points.spacing_x_mm;
  packed.spacing_y_mm = points.spacing_y_mm;
  packed.fit_cofactor = points.fit_cofactor;
  packed.z_noise_sigma_mm = points.z_noise_sigma_mm;
  packed.point_count = points.size();
  const auto n = static_cast<std::size_t>(points.size());

  auto streams = std::make_shared<PackedStreams>();
  streams->occupancy_runs = encode_occupied_cell_runs(points.cell_point);

  std::vector<Units> units(n);
  for (int c = 0; c < kChannels; ++c) {
    CoefficientCoding& coding = packed.coefficients[static_cast<std::size_t>(c)];
    coding.step = coefficient_step(points, c);
    for (std::size_t i = 0; i < n; ++i)
      units[i][static_cast<std::size_t>(c)] =
          quantize(points.surface(c, static_cast<Eigen::Index>(i)), coding.step);
    if (n == 0) continue;
    const auto [low, high] =
        std::minmax_element(units.begin(), units.end(), [c](const Units& a, const Units& b) {
          return a[static_cast<std::size_t>(c)] < b[static_cast<std::size_t>(c)];
        });
    coding.low = (*low)[static_cast<std::size_t>(c)];
    coding.high = (*high)[static_cast<std::size_t>(c)];
  }
  for (int c = 0; c < kChannels; ++c) {
    const Derivative& derivative = kDerivatives[c];
    if (derivative.along_x < 0) continue;
    CoefficientCoding& coding = packed.coefficients[static_cast<std::size_t>(c)];
    coding.ratio_x = derivative_ratio(
        derivative.factor_x, points.spacing_x_mm,
        packed.coefficients[static_cast<std::size_t>(derivative.along_x)].step, coding.step);
    coding.ratio_y = derivative_ratio(
        derivative.factor_y, points.spacing_y_mm,
        packed.coefficients[static_cast<std::size_t>(derivative.along_y)].step, coding.step);
  }

  // Per coefficient the predictor and Rice parameter that code it shortest.
  std::vector<std::size_t> point_cells(n);
  for (std::size_t cell = 0; cell < points.cell_point.size(); ++cell)
    if (points.cell_point[cell] >= 0)
      point_cells[static_cast<std::size_t>(points.cell_point[cell])] = cell;
  std::vector<Neighbours> neighbours(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t width = static_cast<std::size_t>(points.grid_width);
    neighbours[i] = neighbours_of(points.cell_point, units, points.grid_width, point_cells[i],
                                  point_cells[i] % width, point_cells[i] / width);
  }
  std::vector<std::uint32_t> zigzagged(n);
  for (int c = 0; c < kChannels; ++c) {
    CoefficientCoding& coding = packed.coefficients[static_cast<std::size_t>(c)];
    std::uint64_t fewest_bits = std::numeric_limits<std::uint64_t>::max();
    for (int predictor = 0; predictor < kCoefficientPredictors; ++predictor) {
      if (static_cast<CoefficientPredictor>(predictor) ==
              CoefficientPredictor::kDerivativeTrapezoid &&
          kDerivatives[c].along_x < 0)
        continue;
      CoefficientCoding trial = coding;
      trial.predictor = static_cast<std::uint8_t>(predictor);
      PackedRegistrationPoints with_trial = packed;
      with_trial.coefficients[static_cast<std::size_t>(c)] = trial;
      for (std::size_t i = 0; i < n; ++i)
        zigzagged[i] = zigzag(units[i][static_cast<std::size_t>(c)] -
                              predict(with_trial, c, neighbours[i], units[i]));
      const auto [k, bits] = best_rice_bits(zigzagged);
      if (bits < fewest_bits) {
        fewest_bits = bits;
        coding.predictor = trial.predictor;
        coding.rice_bits = static_cast<std::uint8_t>(k);
      }
    }
  }
  for (int c = 0; c < kChannels; ++c) {
    CoefficientCoding& coding = packed.coefficients[static_cast<std::size_t>(c)];
    if (!(coding.step > 0)) continue;
    BitWriter bits;
    for (std::size_t i = 0; i < n; ++i)
      bits.put_rice(
          units[i][static_cast<std::size_t>(c)] - predict(packed, c, neighbours[i], units[i]),
          coding.rice_bits);
    const std::vector<std::uint8_t>& stream = bits.finish();
    coding.stream_bytes = static_cast<std::uint32_t>(stream.size());
    streams->coefficient_bits.insert(streams->coefficient_bits.end(), stream.begin(), stream.end());
  }
  packed.occupancy_runs = streams->occupancy_runs;
  packed.coefficient_bits = streams->coefficient_bits;
  packed.storage = std::move(streams);
  return packed;
}

bool packed_registration_points_consistent(const PackedRegistrationPoints& packed) {
  std::uint64_t stream_bytes = 0;
  if (packed.grid_width < 0 || packed.grid_height < 0 || packed.point_count < 0) return false;
  if (static_cast<std::uint64_t>(packed.grid_width) *
          static_cast<std::uint64_t>(packed.grid_height) >
      std::uint64_t{1} << 32)
    return false;
  for (const CoefficientCoding& coding : packed.coefficients) {
    if (!(coding.step >= 0) || !std::isfinite(coding.step)) return false;
    if (coding.low > coding.high || coding.low < -kMaxUnits || coding.high > kMaxUnits)
      return false;
    if (coding.predictor >= kCoefficientPredictors || coding.rice_bits > kMaxRiceBits) return false;
    if (std::abs(coding.ratio_x) > kMaxDerivativeRatio ||
        std::abs(coding.ratio_y) > kMaxDerivativeRatio)
      return false;
    stream_bytes += coding.stream_bytes;
  }
  if (stream_bytes != packed.coefficient_bits.size()) return false;
  return visit_occupied_cell_runs(packed.occupancy_runs, grid_cells(packed), point_count(packed),
                                  [](std::size_t, std::size_t) {});
}

RegistrationPoints unpack_registration_points(const PackedRegistrationPoints& packed) {
  RegistrationPoints points;
  points.grid_width = std::max(packed.grid_width, 0);
  points.grid_height = std::max(packed.grid_height, 0);
  points.origin_x_mm = packed.origin_x_mm;
  points.origin_y_mm = packed.origin_y_mm;
  points.spacing_x_mm = packed.spacing_x_mm;
  points.spacing_y_mm = packed.spacing_y_mm;
  points.fit_cofactor = packed.fit_cofactor;
  points.z_noise_sigma_mm = packed.z_noise_sigma_mm;

  points.cell_point.assign(grid_cells(packed), -1);
  std::vector<std::size_t> point_cells;
  visit_occupied_cell_runs(packed.occupancy_runs, grid_cells(packed), point_count(packed),
                           [&](std::size_t first, std::size_t end) {
                             for (std::size_t cell = first; cell < end; ++cell) {
                               points.cell_point[cell] =
                                   static_cast<std::int32_t>(point_cells.size());
                               point_cells.push_back(cell);
                             }
                           });
  const auto n = static_cast<int>(point_cells.size());
  points.position_mm.resize(3, n);
  points.normal.resize(3, n);
  points.surface.resize(kSurfaceCoefficients, n);
  points.residual_rms_mm.setConstant(n, packed.z_noise_sigma_mm);

  std::vector<Units> units(static_cast<std::size_t>(n));
  // Each coefficient's stream (cut to the bytes there are: any streams decode).
  std::array<BitReader, kChannels> bits{};
  std::size_t offset = 0;
  for (int c = 0; c < kChannels; ++c) {
    const std::size_t start = std::min(offset, packed.coefficient_bits.size());
    const std::size_t length =
        std::min<std::size_t>(packed.coefficients[static_cast<std::size_t>(c)].stream_bytes,
                              packed.coefficient_bits.size() - start);
    bits[static_cast<std::size_t>(c)] = BitReader(packed.coefficient_bits.subspan(start, length));
    offset = start + length;
  }
  const auto width = static_cast<std::size_t>(std::max(packed.grid_width, 1));
  std::size_t u = 0, v = 0, row_start = 0;  // of the point's cell, without a division each
  for (int i = 0; i < n; ++i) {
    const std::size_t cell = point_cells[static_cast<std::size_t>(i)];
    while (cell >= row_start + width) {
      row_start += width;
      ++v;
    }
    u = cell - row_start;
    const Neighbours near = neighbours_of(points.cell_point, units, packed.grid_width, cell, u, v);
    Units& here = units[static_cast<std::size_t>(i)];
    const auto decode = [&]<int c>() {
      const CoefficientCoding& coding = packed.coefficients[c];
      std::int64_t value = 0;
      if (coding.step > 0)
        value = clamp_units(predict(packed, c, near, here) + bits[c].get_rice(coding.rice_bits),
                            coding);
      here[c] = static_cast<std::int32_t>(value);
      points.surface(c, i) = static_cast<double>(value) * coding.step;
    };
    // Each derivative before what kDerivativeTrapezoid predicts from it: the curvatures
    // before the slopes, the slopes before the height.
    decode.template operator()<kCurveXX>();
    decode.template operator()<kCurveXY>();
    decode.template operator()<kCurveYY>();
    decode.template operator()<kSlopeX>();
    decode.template operator()<kSlopeY>();
    decode.template operator()<kHeight>();
    const double a = points.surface(kSlopeX, i), b = points.surface(kSlopeY, i);
    points.position_mm.col(i) << packed.origin_x_mm + static_cast<double>(u) * packed.spacing_x_mm,
        packed.origin_y_mm + static_cast<double>(v) * packed.spacing_y_mm,
        points.surface(kHeight, i);
    points.normal.col(i) = Eigen::Vector3d(-a, -b, 1.0) / std::sqrt(1.0 + a * a + b * b);
  }
  return points;
}

}  // namespace cosmos
