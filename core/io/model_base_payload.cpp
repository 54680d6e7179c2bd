#include "core/io/model_base_payload.hpp"

#include <bit>
#include <cstring>

#include "core/io/model_base_generated.h"
#include "core/modelbase/model_base_ranges.hpp"

namespace cosmos {
namespace {

// The registration arrays are used in place: FlatBuffers stores scalars little-endian.
static_assert(std::endian::native == std::endian::little, "the model base is read in place");

using flatbuffers::FlatBufferBuilder;
using flatbuffers::Offset;

fb::Vec3 vec3(const Eigen::Vector3d& v) { return fb::Vec3(v.x(), v.y(), v.z()); }
Eigen::Vector3d vec3(const fb::Vec3* v) {
  return v ? Eigen::Vector3d(v->x(), v->y(), v->z()) : Eigen::Vector3d::Zero();
}

fb::Transform transform(const RigidTransform& T) {
  const Eigen::Matrix3d& R = T.rotation;
  return fb::Transform(fb::Vec3(R(0, 0), R(0, 1), R(0, 2)), fb::Vec3(R(1, 0), R(1, 1), R(1, 2)),
                       fb::Vec3(R(2, 0), R(2, 1), R(2, 2)), vec3(T.translation_mm));
}

RigidTransform transform(const fb::Transform* T) {
  RigidTransform out;
  if (!T) return out;
  out.rotation << vec3(&T->row0()).transpose(), vec3(&T->row1()).transpose(),
      vec3(&T->row2()).transpose();
  out.translation_mm = vec3(&T->translation_mm());
  return out;
}

Offset<fb::Patch> encode_patch(FlatBufferBuilder& b, const Csmp& p) {
  std::vector<fb::PatchNeighbor> neighbors;
  neighbors.reserve(p.neighbors.size());
  for (const PatchNeighbor& n : p.neighbors)
    neighbors.emplace_back(n.patch, n.shared_boundary_pixels);
  const auto neighbor_vector = b.CreateVectorOfStructs(neighbors);
  const fb::Vec3 normal = vec3(p.mean_normal), centroid = vec3(p.centroid_mm);
  return fb::CreatePatch(b, p.id, p.area_mm2, &normal, p.shape_index, p.shape_index_min,
                         p.shape_index_max, p.mean_curvedness_per_mm, &centroid, p.pixels, p.planar,
                         neighbor_vector);
}

Offset<fb::GaussMapPoint> encode_gauss_point(FlatBufferBuilder& b, const GaussMapPoint& g) {
  std::vector<Offset<fb::SupportTerm>> terms;
  for (const SupportTerm& t : g.terms) {
    const auto patches = b.CreateVector(t.patches);
    terms.push_back(
        fb::CreateSupportTerm(b, t.shape_index, t.area_mm2, t.curvedness_area, patches));
  }
  const auto term_vector = b.CreateVector(terms);
  const fb::Vec3 direction = vec3(g.direction);
  return fb::CreateGaussMapPoint(b, &direction, term_vector);
}

bool packed_is_set(const PackedRegistrationPoints& p) {
  return p.size() > 0 || p.grid_width > 0 || p.grid_height > 0;
}

// The fit's cofactor depends only on the window and the grid spacing (registration_points.hpp),
// so a base's views share a few: each distinct one is written once and referenced by every
// view that has it (FlatBuffers offsets may point to the same vector).
class SharedCofactors {
 public:
  using Cofactor = Eigen::Matrix<double, kSurfaceCoefficients, kSurfaceCoefficients>;
  Offset<flatbuffers::Vector<double>> offset(FlatBufferBuilder& b, const Cofactor& cofactor) {
    for (const auto& [known, offset] : written_)
      if (std::memcmp(known.data(), cofactor.data(), sizeof(double) * known.size()) == 0)
        return offset;
    const auto offset = b.CreateVector(cofactor.data(), static_cast<std::size_t>(cofactor.size()));
    written_.emplace_back(cofactor, offset);
    return offset;
  }

 private:
  std::vector<std::pair<Cofactor, Offset<flatbuffers::Vector<double>>>> written_;
};

Offset<fb::RegistrationPoints> encode_registration(FlatBufferBuilder& b, const ModelBaseView& view,
                                                   SharedCofactors& cofactors) {
  const PackedRegistrationPoints packed = packed_is_set(view.registration_packed)
                                              ? view.registration_packed
                                              : pack_registration_points(view.registration);
  const auto runs = b.CreateVector(packed.occupancy_runs.data(), packed.occupancy_runs.size());
  const auto bits = b.CreateVector(packed.coefficient_bits.data(), packed.coefficient_bits.size());
  std::vector<fb::CoefficientCoding> codings;
  for (const CoefficientCoding& c : packed.coefficients)
    codings.emplace_back(c.step, c.low, c.high, c.predictor, c.rice_bits, c.ratio_x, c.ratio_y,
                         c.stream_bytes);
  const auto coefficients = b.CreateVectorOfStructs(codings);
  const auto cofactor = cofactors.offset(b, packed.fit_cofactor);
  return fb::CreateRegistrationPoints(b, packed.grid_width, packed.grid_height, packed.origin_x_mm,
                                      packed.origin_y_mm, packed.spacing_x_mm, packed.spacing_y_mm,
                                      packed.point_count, runs, bits, coefficients, cofactor,
                                      packed.z_noise_sigma_mm);
}

Offset<fb::View> encode_view(FlatBufferBuilder& b, const ModelBaseView& view,
                             SharedCofactors& cofactors) {
  std::vector<Offset<fb::Patch>> patches;
  for (const Csmp& p : view.cosmos.patches) patches.push_back(encode_patch(b, p));
  const auto patch_vector = b.CreateVector(patches);
  std::vector<Offset<fb::GaussMapPoint>> gauss_map;
  for (const GaussMapPoint& g : view.cosmos.gauss_map)
    gauss_map.push_back(encode_gauss_point(b, g));
  const auto gauss_vector = b.CreateVector(gauss_map);
  const auto moments = b.CreateVector(view.moments.data(), view.moments.size());
  const auto registration = encode_registration(b, view, cofactors);
  const fb::Vec3 direction = vec3(view.direction_part);
  const fb::Transform T_scanner_part = transform(view.T_scanner_part);
  const fb::Vec3 centroid = vec3(view.control_point_centroid_mm);
  const fb::ViewExtent extent(view.extent.highest_mm, view.extent.widest_mm,
                              view.extent.narrowest_mm);
  const auto signature =
      b.CreateVector(view.signature.cumulative.data(), view.signature.cumulative.size());
  return fb::CreateView(b, view.part_index, view.view_index, &direction, &T_scanner_part,
                        patch_vector, gauss_vector, view.cosmos.visible_area_mm2, moments,
                        registration, &centroid, &extent, signature);
}

}  // namespace

std::size_t estimated_payload_bytes(const ModelBase& base) {
  std::size_t bytes = 4096 + base.catalog_hash.size() + base.parameters_text.size();
  for (const ModelPart& part : base.parts)
    bytes += 256 + part.name.size() + part.mesh.size() + 96 * part.resting_poses.size() +
             32 * part.hull_vertices_mm.size() + part.surface_voxels.occupied_runs.size() +
             32 * part.surface_sample_mm.size() + 4 * part.confusable_parts.size();
  for (const ViewCluster& cluster : base.clusters) bytes += 160 + 4 * cluster.views.size();
  for (const ModelBaseView& view : base.views) {
    const bool packed = packed_is_set(view.registration_packed);
    const std::size_t points = static_cast<std::size_t>(packed ? view.registration_packed.size()
                                                               : view.registration.size());
    // The Rice codes take a few bytes per point; escapes, a few more: 12 is far above.
    const std::size_t coded = packed ? view.registration_packed.packed_bytes() : 12 * points;
    bytes += 1024 + coded + view.registration.cell_point.size() / 8;
    for (const Csmp& p : view.cosmos.patches) bytes += 160 + 8 * p.neighbors.size();
    for (const GaussMapPoint& g : view.cosmos.gauss_map) {
      bytes += 64;
      for (const SupportTerm& t : g.terms) bytes += 64 + 4 * t.patches.size();
    }
  }
  return bytes;
}

void encode_model_base(const ModelBase& base, FlatBufferBuilder& b) {
  std::vector<Offset<fb::Part>> parts;
  for (const ModelPart& part : base.parts) {
    const auto name = b.CreateString(part.name);
    const auto mesh = b.CreateString(part.mesh);
    std::vector<fb::RestingPose> resting;
    for (const RestingPose& pose : part.resting_poses)
      resting.emplace_back(
          transform(RigidTransform{pose.R_belt_part, Eigen::Vector3d(0, 0, pose.height_mm)}),
          pose.probability);
    const auto resting_vector = b.CreateVectorOfStructs(resting);
    std::vector<fb::Vec3> hull;
    for (const Eigen::Vector3d& vertex : part.hull_vertices_mm) hull.push_back(vec3(vertex));
    const auto hull_vector = b.CreateVectorOfStructs(hull);
    const PartSurfaceVoxels& voxels = part.surface_voxels;
    const auto runs = b.CreateVector(voxels.occupied_runs);
    const fb::Vec3 origin = vec3(voxels.origin_mm);
    const auto surface_voxels =
        fb::CreateSurfaceVoxels(b, &origin, voxels.voxel_mm, voxels.size[0], voxels.size[1],
                                voxels.size[2], voxels.occupied_voxels, runs);
    std::vector<fb::Vec3> sample;
    for (const Eigen::Vector3d& point : part.surface_sample_mm) sample.push_back(vec3(point));
    const auto sample_vector = b.CreateVectorOfStructs(sample);
    const auto confusable = b.CreateVector(part.confusable_parts);
    parts.push_back(fb::CreatePart(b, name, mesh, part.size_mm, part.diameter_mm, part.symmetric,
                                   resting_vector, hull_vector, surface_voxels, sample_vector,
                                   confusable));
  }
  const auto part_vector = b.CreateVector(parts);
  std::vector<Offset<fb::View>> views;
  views.reserve(base.views.size());
  SharedCofactors cofactors;
  for (const ModelBaseView& view : base.views) views.push_back(encode_view(b, view, cofactors));
  const auto view_vector = b.CreateVector(views);
  std::vector<Offset<fb::Cluster>> clusters;
  for (const ViewCluster& cluster : base.clusters) {
    const auto members = b.CreateVector(cluster.views);
    const auto centroid = b.CreateVector(cluster.centroid.data(), cluster.centroid.size());
    clusters.push_back(fb::CreateCluster(b, cluster.part_index, members, centroid));
  }
  const auto cluster_vector = b.CreateVector(clusters);
  const auto catalog_hash = b.CreateString(base.catalog_hash);
  const auto parameters_text = b.CreateString(base.parameters_text);
  b.Finish(fb::CreateModelBase(b, ModelBase::kFormatVersion, catalog_hash, parameters_text,
                               part_vector, view_vector, cluster_vector),
           fb::ModelBaseIdentifier());
}

namespace {

template <class T>
std::span<const T> span_of(const flatbuffers::Vector<T>* v) {
  return v ? std::span<const T>(v->data(), v->size()) : std::span<const T>();
}

// Element i of a vector of structs, copied out: the verifier checks a vector's length word's
// alignment, not its elements', so a crafted payload may place doubles off their 8 bytes.
template <class Struct>
Struct struct_at(const flatbuffers::Vector<const Struct*>& v, std::size_t i) {
  Struct out;
  std::memcpy(static_cast<void*>(&out), v.Data() + i * sizeof(Struct), sizeof(Struct));
  return out;
}

std::string view_label(std::size_t v) { return "view " + std::to_string(v); }

// A fixed-length array (the moments, a signature's bins): refused unless the stored vector has
// exactly its length, `what` naming its entries in the message.
template <class T, std::size_t N>
std::optional<std::string> decode_array(const flatbuffers::Vector<T>* in, std::array<T, N>& out,
                                        const std::string& what, const std::string& where) {
  if (!in || in->size() != N)
    return where + ": " + std::to_string(in ? in->size() : 0) + " " + what + ", expected " +
           std::to_string(N);
  std::copy(in->begin(), in->end(), out.begin());
  return std::nullopt;
}

CosmosView decode_cosmos(const fb::View& in) {
  CosmosView cosmos;
  cosmos.visible_area_mm2 = in.visible_area_mm2();
  if (const auto* patches = in.patches()) {
    cosmos.patches.reserve(patches->size());
    for (const fb::Patch* p : *patches) {
      Csmp& csmp = cosmos.patches.emplace_back();
      csmp = Csmp{p->id(),
                  p->area_mm2(),
                  vec3(p->mean_normal()),
                  p->shape_index(),
                  p->shape_index_min(),
                  p->shape_index_max(),
                  p->mean_curvedness_per_mm(),
                  vec3(p->centroid_mm()),
                  p->pixels(),
                  p->planar(),
                  {}};
      if (!p->neighbors()) continue;
      csmp.neighbors.reserve(p->neighbors()->size());
      for (const fb::PatchNeighbor* n : *p->neighbors())
        csmp.neighbors.push_back({n->patch(), n->shared_boundary_pixels()});
    }
  }
  if (const auto* gauss_map = in.gauss_map()) {
    cosmos.gauss_map.reserve(gauss_map->size());
    for (const fb::GaussMapPoint* g : *gauss_map) {
      GaussMapPoint& point = cosmos.gauss_map.emplace_back();
      point.direction = vec3(g->direction());
      if (!g->terms()) continue;
      for (const fb::SupportTerm* t : *g->terms()) {
        const auto patches = span_of(t->patches());
        point.terms.push_back({t->shape_index(),
                               t->area_mm2(),
                               t->curvedness_area(),
                               {patches.begin(), patches.end()}});
      }
    }
  }
  return cosmos;
}

std::optional<std::string> decode_registration(const fb::RegistrationPoints* in,
                                               const std::shared_ptr<const void>& owner,
                                               PackedRegistrationPoints& out,
                                               const std::string& where) {
  if (!in) return where + ": no registration points table";
  out.grid_width = in->grid_width();
  out.grid_height = in->grid_height();
  out.origin_x_mm = in->origin_x_mm();
  out.origin_y_mm = in->origin_y_mm();
  out.spacing_x_mm = in->spacing_x_mm();
  out.spacing_y_mm = in->spacing_y_mm();
  out.point_count = in->point_count();
  out.occupancy_runs = span_of(in->occupancy_runs());
  out.coefficient_bits = span_of(in->coefficient_bits());
  out.z_noise_sigma_mm = in->z_noise_sigma_mm();
  out.storage = owner;
  const auto* codings = in->coefficients();
  if (!codings || codings->size() != out.coefficients.size())
    return where + ": " + std::to_string(codings ? codings->size() : 0) +
           " coefficient codings, expected " + std::to_string(out.coefficients.size());
  for (std::size_t c = 0; c < out.coefficients.size(); ++c) {
    const fb::CoefficientCoding coding = struct_at(*codings, c);
    out.coefficients[c] = {coding.step(),      coding.low(),         coding.high(),
                           coding.predictor(), coding.rice_bits(),   coding.ratio_x(),
                           coding.ratio_y(),   coding.stream_bytes()};
  }
  const auto cofactor = span_of(in->fit_cofactor());
  if (cofactor.size() != static_cast<std::size_t>(out.fit_cofactor.size()))
    return where + ": fit cofactor has " + std::to_string(cofactor.size()) + " values, expected 36";
  std::memcpy(out.fit_cofactor.data(), cofactor.data(), sizeof(double) * cofactor.size());
  if (!packed_registration_points_consistent(out))
    return where + ": registration streams do not match their header (" +
           std::to_string(out.grid_width) + " x " + std::to_string(out.grid_height) + " cells, " +
           std::to_string(out.size()) + " points)";
  return std::nullopt;
}

std::optional<std::string> decode_surface_voxels(const fb::SurfaceVoxels* in,
                                                 PartSurfaceVoxels& out, const std::string& where) {
  if (!in) return where + ": no surface voxels table";
  out.origin_mm = vec3(in->origin_mm());
  out.voxel_mm = in->voxel_mm();
  out.size = {in->size_x(), in->size_y(), in->size_z()};
  out.occupied_voxels = in->occupied_voxels();
  const auto runs = span_of(in->occupied_runs());
  out.occupied_runs.assign(runs.begin(), runs.end());
  if (!part_surface_voxels_consistent(out))
    return where + ": surface voxels do not match their grid (" + std::to_string(out.size[0]) +
           " x " + std::to_string(out.size[1]) + " x " + std::to_string(out.size[2]) + " voxels, " +
           std::to_string(out.occupied_voxels) + " occupied)";
  return std::nullopt;
}

}  // namespace

std::optional<std::string> decode_model_base(const std::uint8_t* payload, std::size_t payload_bytes,
                                             std::shared_ptr<const void> owner, ModelBase& out) {
  // The root offset and the identifier come first: a shorter payload has neither (and the
  // identifier check would read past it).
  if (payload_bytes < 8)
    return "payload of " + std::to_string(payload_bytes) + " bytes, shorter than its 8-byte start";
  if (!fb::ModelBaseBufferHasIdentifier(payload)) return std::string("no CSMB payload identifier");
  // The defaults (one million tables) are too few for 20 x 320 views of ~30 tables each.
  flatbuffers::Verifier verifier(payload, payload_bytes, 64, 1u << 30);
  if (!fb::VerifyModelBaseBuffer(verifier))
    return std::string("FlatBuffers verifier rejects the payload");
  const fb::ModelBase* in = fb::GetModelBase(payload);
  if (in->format_version() != ModelBase::kFormatVersion)
    return "payload says format version " + std::to_string(in->format_version()) +
           ", header says " + std::to_string(ModelBase::kFormatVersion);

  out = ModelBase{};
  out.catalog_hash = in->catalog_hash() ? in->catalog_hash()->str() : "";
  out.parameters_text = in->parameters_text() ? in->parameters_text()->str() : "";
  if (const auto* parts = in->parts()) {
    for (const fb::Part* p : *parts) {
      ModelPart& part = out.parts.emplace_back();
      part = {p->name() ? p->name()->str() : "",
              p->mesh() ? p->mesh()->str() : "",
              p->size_mm(),
              p->diameter_mm(),
              p->symmetric(),
              {},
              {},
              {},
              {},
              {}};
      if (const auto* resting = p->resting_poses())
        for (std::size_t r = 0; r < resting->size(); ++r) {
          const fb::RestingPose pose = struct_at(*resting, r);
          const RigidTransform T_belt_part = transform(&pose.t_belt_part());
          part.resting_poses.push_back(
              {T_belt_part.rotation, T_belt_part.translation_mm.z(), pose.probability()});
        }
      if (const auto* hull = p->hull_vertices_mm())
        for (std::size_t k = 0; k < hull->size(); ++k) {
          const fb::Vec3 vertex = struct_at(*hull, k);
          part.hull_vertices_mm.push_back(vec3(&vertex));
        }
      if (auto error = decode_surface_voxels(p->surface_voxels(), part.surface_voxels,
                                             "part " + std::to_string(out.parts.size() - 1)))
        return error;
      if (const auto* sample = p->surface_sample_mm())
        for (std::size_t k = 0; k < sample->size(); ++k) {
          const fb::Vec3 point = struct_at(*sample, k);
          part.surface_sample_mm.push_back(vec3(&point));
        }
    }
  }
  const int part_count = static_cast<int>(out.parts.size());
  for (std::size_t p = 0; p < out.parts.size(); ++p) {
    const auto confusable =
        span_of(in->parts()->Get(static_cast<flatbuffers::uoffset_t>(p))->confusable_parts());
    for (int other : confusable) {
      if (other < 0 || other >= part_count)
        return "part " + std::to_string(p) + ": confusable part " + std::to_string(other) +
               " out of range";
      out.parts[p].confusable_parts.push_back(other);
    }
  }
  if (const auto* views = in->views()) {
    out.views.resize(views->size());
    for (std::size_t v = 0; v < views->size(); ++v) {
      const fb::View& view = *views->Get(static_cast<flatbuffers::uoffset_t>(v));
      ModelBaseView& view_out = out.views[v];
      view_out.part_index = view.part_index();
      if (view_out.part_index < 0 || view_out.part_index >= part_count)
        return view_label(v) + ": part index " + std::to_string(view_out.part_index) +
               " out of range";
      view_out.view_index = view.view_index();
      view_out.direction_part = vec3(view.direction_part());
      view_out.T_scanner_part = transform(view.t_scanner_part());
      view_out.control_point_centroid_mm = vec3(view.control_point_centroid_mm());
      if (const fb::ViewExtent* extent = view.extent())
        view_out.extent = {extent->highest_mm(), extent->widest_mm(), extent->narrowest_mm()};
      view_out.cosmos = decode_cosmos(view);
      if (auto error = decode_array(view.moments(), view_out.moments, "moments", view_label(v)))
        return error;
      if (auto error = decode_array(view.signature(), view_out.signature.cumulative,
                                    "signature bins", view_label(v)))
        return error;
      if (auto error = decode_registration(view.registration(), owner, view_out.registration_packed,
                                           view_label(v)))
        return error;
    }
  }
  if (const auto* clusters = in->clusters()) {
    for (std::size_t c = 0; c < clusters->size(); ++c) {
      const fb::Cluster& cluster = *clusters->Get(static_cast<flatbuffers::uoffset_t>(c));
      const std::string where = "cluster " + std::to_string(c);
      ViewCluster& cluster_out = out.clusters.emplace_back();
      cluster_out.part_index = cluster.part_index();
      if (cluster_out.part_index < 0 || cluster_out.part_index >= part_count)
        return where + ": part index " + std::to_string(cluster_out.part_index) + " out of range";
      const auto members = span_of(cluster.views());
      for (int member : members) {
        if (member < 0 || static_cast<std::size_t>(member) >= out.views.size())
          return where + ": view " + std::to_string(member) + " out of range";
        if (out.views[static_cast<std::size_t>(member)].part_index != cluster_out.part_index)
          return where + ": view " + std::to_string(member) + " belongs to another part";
      }
      cluster_out.views.assign(members.begin(), members.end());
      if (auto error = decode_array(cluster.centroid(), cluster_out.centroid, "moments", where))
        return error;
    }
  }
  // The verifier proved the offsets; the values the recognizer trusts are checked here.
  return model_base_out_of_range(out);
}

}  // namespace cosmos
