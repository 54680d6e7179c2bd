#pragma once
// Four columns at a time or one: the lanes of the separable window fit's fused kernels
// (separable_window_fit.cpp), written once for both. GCC vector extensions, so the same code
// becomes AVX2 registers when compiled for them and SSE2 pairs otherwise; the one-column
// form takes the row's last columns.
#include <cmath>
#include <cstdint>
#include <cstring>

namespace cosmos::window_lanes {

using Double4 = double __attribute__((vector_size(32)));
using Float4 = float __attribute__((vector_size(16)));

template <class V>
struct Lanes;
template <>
struct Lanes<double> {
  using Floats = float;
  static double load(const double* p) { return *p; }
  static float load(const float* p) { return *p; }
  static double widen(float v) { return v; }
  static float narrow(double v) { return static_cast<float>(v); }
  static double broadcast(double v) { return v; }
  static double max(double a, double b) { return a > b ? a : b; }
  static float min(float a, float b) { return a < b ? a : b; }
  static float max(float a, float b) { return a > b ? a : b; }
  static void store(float* p, float v) { *p = v; }
  static void store(double* p, double v) { *p = v; }
  static void store_complete(std::uint8_t* p, double residual, double range, double limit) {
    *p = std::isfinite(residual) && range <= limit;
  }
};
template <>
struct Lanes<Double4> {
  using Floats = Float4;
  static Double4 load(const double* p) {
    Double4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static Float4 load(const float* p) {
    Float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static Double4 widen(Float4 v) { return __builtin_convertvector(v, Double4); }
  static Float4 narrow(Double4 v) { return __builtin_convertvector(v, Float4); }
  static Double4 broadcast(double v) { return Double4{v, v, v, v}; }
  static Double4 max(Double4 a, Double4 b) { return a > b ? a : b; }
  static Float4 min(Float4 a, Float4 b) { return a < b ? a : b; }
  static Float4 max(Float4 a, Float4 b) { return a > b ? a : b; }
  static void store(float* p, Float4 v) { std::memcpy(p, &v, sizeof v); }
  static void store(double* p, Double4 v) { std::memcpy(p, &v, sizeof v); }
  static void store_complete(std::uint8_t* p, Double4 residual, Double4 range, double limit) {
    for (int lane = 0; lane < 4; ++lane)
      p[lane] = std::isfinite(residual[lane]) && range[lane] <= limit;
  }
};

}  // namespace cosmos::window_lanes
