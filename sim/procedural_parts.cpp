#include "sim/procedural_parts.hpp"

#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "core/input_error.hpp"
#include "sim/seeded_random.hpp"

namespace cosmos {
namespace {

using Outline = std::vector<Eigen::Vector2d>;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double signed_area(std::span<const Eigen::Vector2d> outline) {
  double twice = 0.0;
  for (std::size_t i = 0; i < outline.size(); ++i)
    twice += cross(outline[i], outline[(i + 1) % outline.size()]);
  return 0.5 * twice;
}

bool inside_triangle(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                     const Eigen::Vector2d& c) {
  return cross(b - a, p - a) >= 0.0 && cross(c - b, p - b) >= 0.0 && cross(a - c, p - c) >= 0.0;
}

// Ear clipping of a simple counter-clockwise polygon: corner i is an ear when it turns left
// and no other corner lies in its triangle. Quadratic per ear, ample for a part's outline.
std::vector<Eigen::Vector3i> triangulate(std::span<const Eigen::Vector2d> outline) {
  std::vector<int> remaining(outline.size());
  for (std::size_t i = 0; i < outline.size(); ++i) remaining[i] = static_cast<int>(i);
  std::vector<Eigen::Vector3i> triangles;
  while (remaining.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < remaining.size() && !clipped; ++i) {
      const int a = remaining[(i + remaining.size() - 1) % remaining.size()];
      const int b = remaining[i];
      const int c = remaining[(i + 1) % remaining.size()];
      const Eigen::Vector2d& pa = outline[static_cast<std::size_t>(a)];
      const Eigen::Vector2d& pb = outline[static_cast<std::size_t>(b)];
      const Eigen::Vector2d& pc = outline[static_cast<std::size_t>(c)];
      if (cross(pb - pa, pc - pb) <= 0.0) continue;
      bool empty = true;
      for (int other : remaining)
        if (other != a && other != b && other != c &&
            inside_triangle(outline[static_cast<std::size_t>(other)], pa, pb, pc))
          empty = false;
      if (!empty) continue;
      triangles.emplace_back(a, b, c);
      remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) throw std::invalid_argument("make_extrusion: the outline is not simple");
  }
  triangles.emplace_back(remaining[0], remaining[1], remaining[2]);
  return triangles;
}

struct Family {
  const char* name;
  bool revolved;
  std::function<Outline(SeededRandom&)> shape;  // an outline, or a profile (r, z)
};

double draw(SeededRandom& random, double low, double high) {
  return low + (high - low) * random.uniform();
}

Outline l_bracket(SeededRandom& r) {
  const double a = draw(r, 40, 80), b = draw(r, 30, 60), t = draw(r, 6, 14);
  return {{0, 0}, {a, 0}, {a, t}, {t, t}, {t, b}, {0, b}};
}

// Off-centre web, so no section is mirror symmetric about its own axis.
Outline t_section(SeededRandom& r) {
  const double w = draw(r, 50, 90), flange = draw(r, 6, 14), web_h = draw(r, 25, 55);
  const double web_t = draw(r, 6, 14);
  const double x0 = (w - web_t) / 2 + draw(r, 0.1, 0.3) * w;
  return {{x0, 0},    {x0 + web_t, 0},     {x0 + web_t, web_h},
          {w, web_h}, {w, web_h + flange}, {0, web_h + flange},
          {0, web_h}, {x0, web_h}};
}

// Walls of unequal height.
Outline u_channel(SeededRandom& r) {
  const double w = draw(r, 40, 80), h = draw(r, 25, 50), t = draw(r, 5, 12), base = draw(r, 5, 12);
  const double h2 = draw(r, 0.55, 0.85) * h;
  return {{0, 0}, {w, 0}, {w, h2}, {w - t, h2}, {w - t, base}, {t, base}, {t, h}, {0, h}};
}

Outline z_section(SeededRandom& r) {
  const double a = draw(r, 30, 60), b = draw(r, 20, 50), h = draw(r, 30, 60), t = draw(r, 5, 12);
  return {{0, 0}, {a, 0}, {a, h}, {a + b, h}, {a + b, h + t}, {a - t, h + t}, {a - t, t}, {0, t}};
}

Outline notched_plate(SeededRandom& r) {
  const double w = draw(r, 60, 100), d = draw(r, 40, 70), notch_w = draw(r, 10, 25);
  const double notch_d = draw(r, 10, 0.5 * d), notch_x = draw(r, 0.1, 0.5) * w;
  return {{0, 0},
          {w, 0},
          {w, d},
          {notch_x + notch_w, d},
          {notch_x + notch_w, d - notch_d},
          {notch_x, d - notch_d},
          {notch_x, d},
          {0, d}};
}

// Two to four cylinders, neighbours at least 3 mm apart in radius.
Outline stepped_shaft(SeededRandom& r) {
  const int steps = 2 + static_cast<int>(r.next() % 3);
  Outline profile = {{0, 0}};
  double z = 0, radius = 0;
  for (int s = 0; s < steps; ++s) {
    double next = draw(r, 8, 25);
    while (std::abs(next - radius) < 3) next = draw(r, 8, 25);
    radius = next;
    profile.emplace_back(radius, z);
    z += draw(r, 10, 35);
    profile.emplace_back(radius, z);
  }
  profile.emplace_back(0, z);
  return profile;
}

Outline flanged_bushing(SeededRandom& r) {
  const double flange_r = draw(r, 25, 40), flange_t = draw(r, 5, 12);
  const double body_r = draw(r, 10, 0.7 * flange_r), length = draw(r, 15, 40);
  const double chamfer = draw(r, 1, 3);
  return {{0, 0},
          {flange_r, 0},
          {flange_r, flange_t},
          {body_r, flange_t},
          {body_r, flange_t + length - chamfer},
          {body_r - chamfer, flange_t + length},
          {0, flange_t + length}};
}

Outline knob(SeededRandom& r) {
  const double base_r = draw(r, 15, 30), base_h = draw(r, 5, 15);
  const double top_r = draw(r, 5, 0.8 * base_r), cone_h = draw(r, 10, 30), top_h = draw(r, 5, 20);
  return {{0, 0},
          {base_r, 0},
          {base_r, base_h},
          {top_r, base_h + cone_h},
          {top_r, base_h + cone_h + top_h},
          {0, base_h + cone_h + top_h}};
}

const std::vector<Family>& families() {
  static const std::vector<Family> kFamilies = {
      {"l-bracket", false, l_bracket},
      {"t-section", false, t_section},
      {"u-channel", false, u_channel},
      {"z-section", false, z_section},
      {"notched-plate", false, notched_plate},
      {"stepped-shaft", true, stepped_shaft},
      {"flanged-bushing", true, flanged_bushing},
      {"knob", true, knob},
  };
  return kFamilies;
}

constexpr int kRevolutionSegments = 96;

}  // namespace

TriangleMesh make_extrusion(std::span<const Eigen::Vector2d> outline_mm, double height_mm) {
  if (outline_mm.size() < 3 || !(height_mm > 0.0))
    throw std::invalid_argument("make_extrusion: needs 3 or more points and a height > 0");
  if (!(signed_area(outline_mm) > 0.0))
    throw std::invalid_argument("make_extrusion: the outline must be counter-clockwise");
  const int n = static_cast<int>(outline_mm.size());
  TriangleMesh mesh;
  for (const double z : {0.0, height_mm})
    for (const Eigen::Vector2d& p : outline_mm)
      mesh.vertices.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                 static_cast<float>(z));
  for (const Eigen::Vector3i& t : triangulate(outline_mm)) {
    mesh.triangles.emplace_back(t[0], t[2], t[1]);  // bottom cap, seen from below
    mesh.triangles.emplace_back(t[0] + n, t[1] + n, t[2] + n);
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.triangles.emplace_back(i, j, j + n);
    mesh.triangles.emplace_back(i, j + n, i + n);
  }
  return mesh;
}

TriangleMesh make_revolution(std::span<const Eigen::Vector2d> profile_rz_mm, int segments) {
  const std::size_t n = profile_rz_mm.size();
  if (n < 3 || segments < 3)
    throw std::invalid_argument("make_revolution: needs 3 or more points and 3 or more segments");
  if (profile_rz_mm.front().x() != 0.0 || profile_rz_mm.back().x() != 0.0)
    throw std::invalid_argument("make_revolution: the profile must start and end on the axis");
  for (std::size_t k = 1; k + 1 < n; ++k)
    if (!(profile_rz_mm[k].x() > 0.0))
      throw std::invalid_argument("make_revolution: inner profile points must be off the axis");
  TriangleMesh mesh;
  const auto ring_vertex = [&](std::size_t k, int j) {
    return 1 + static_cast<int>(k - 1) * segments + (j % segments);
  };
  mesh.vertices.emplace_back(0.0f, 0.0f, static_cast<float>(profile_rz_mm.front().y()));
  for (std::size_t k = 1; k + 1 < n; ++k)
    for (int j = 0; j < segments; ++j) {
      const double angle = 2.0 * std::numbers::pi * j / segments;
      const double r = profile_rz_mm[k].x();
      mesh.vertices.emplace_back(static_cast<float>(r * std::cos(angle)),
                                 static_cast<float>(r * std::sin(angle)),
                                 static_cast<float>(profile_rz_mm[k].y()));
    }
  const int top = static_cast<int>(mesh.vertices.size());
  mesh.vertices.emplace_back(0.0f, 0.0f, static_cast<float>(profile_rz_mm.back().y()));
  for (int j = 0; j < segments; ++j) {
    mesh.triangles.emplace_back(0, ring_vertex(1, j + 1), ring_vertex(1, j));
    mesh.triangles.emplace_back(top, ring_vertex(n - 2, j), ring_vertex(n - 2, j + 1));
    for (std::size_t k = 1; k + 2 < n; ++k) {
      mesh.triangles.emplace_back(ring_vertex(k, j), ring_vertex(k, j + 1),
                                  ring_vertex(k + 1, j + 1));
      mesh.triangles.emplace_back(ring_vertex(k, j), ring_vertex(k + 1, j + 1),
                                  ring_vertex(k + 1, j));
    }
  }
  return mesh;
}

std::vector<std::string> procedural_families() {
  std::vector<std::string> names;
  for (const Family& family : families()) names.emplace_back(family.name);
  return names;
}

std::vector<ProceduralPart> procedural_parts(int per_family, std::uint64_t seed) {
  std::vector<ProceduralPart> parts;
  for (std::size_t f = 0; f < families().size(); ++f) {
    const Family& family = families()[f];
    for (int i = 1; i <= per_family; ++i) {
      SeededRandom random(mix_seed(seed, f * 1000 + static_cast<std::uint64_t>(i)));
      const Outline shape = family.shape(random);
      ProceduralPart part;
      part.name = std::string(family.name) + "-" + std::to_string(i);
      part.symmetric = family.revolved;
      part.mesh = family.revolved ? make_revolution(shape, kRevolutionSegments)
                                  : make_extrusion(shape, draw(random, 15, 45));
      parts.push_back(std::move(part));
    }
  }
  return parts;
}

void write_off_file(const TriangleMesh& mesh, const std::filesystem::path& path) {
  std::ofstream file(path, std::ios::binary);
  file << "OFF\n" << mesh.vertices.size() << ' ' << mesh.triangles.size() << " 0\n";
  file.precision(9);
  for (const Eigen::Vector3f& v : mesh.vertices)
    file << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const Eigen::Vector3i& t : mesh.triangles)
    file << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  file.close();
  if (!file) throw InputError(path.string() + ": cannot write the mesh");
}

}  // namespace cosmos
