#include <dlfl/schemes/detail/meng_prautzsch_common.h>

#include <dlfl/dense_mesh.h>

namespace dlfl::detail {

MpStepInput::MpStepInput(const char* scheme, const Mesh& input, const MpStepParams& params,
                         ElementKind taus_per) {
  check_mp_params(scheme, params.tau, params.ratio, params.center, params.random);
  mesh_ = &dense_mesh(input, storage_);
  center_ = params.center.value_or(vertex_centroid(*mesh_));
  require_convex_polyhedron(*mesh_, center_, scheme);
  check_output_size(scheme, 4.0 * double(mesh_->num_edges()));
  const std::size_t taus = taus_per == ElementKind::face ? mesh_->num_faces() : mesh_->num_vertices();
  choices_ = mp_choices(mesh_->num_edges(), taus, params.ratio, params.tau, params.random);
}

MpFaceLayout mp_face_layout(const Mesh& m, std::uint32_t count, std::uint32_t size) {
  const auto [nv, ne, nf, nc] = dense_counts(m);
  MpFaceLayout layout{std::vector<std::uint32_t>(std::size_t(nf) + count + 1),
                      std::vector<std::uint32_t>(nc)};
  std::uint32_t k = 0;
  for (std::uint32_t f = 0; f < nf; ++f) {
    layout.offsets[f] = k;
    for (CornerId c : m.corners(FaceId(f))) layout.position[c.index()] = k++;
  }
  for (std::uint32_t i = 0; i <= count; ++i) layout.offsets[nf + i] = nc + size * i;
  return layout;
}

}  // namespace dlfl::detail
