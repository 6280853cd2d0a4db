#pragma once
// Vector pictures for papers: a scene as an SVG line drawing, faces filled with the colours of the raster
// picture (flat shading) and depth-sorted, edges as their outlines.

#include <filesystem>
#include <iosfwd>

#include <dlfl/render/camera.h>
#include <dlfl/render/scene.h>
#include <dlfl/render/shading.h>

namespace dlfl {

class FileBatch;

/// Writes `scene` as SVG 1.1 to `out`, width x height of the camera in user units (pixels). Polygons,
/// curves and points are sorted by the nearness of their centroids and painted far to near (the painter's
/// algorithm: exact for meshes whose faces do not interpenetrate, which subdivision meshes are; cyclic
/// overlaps are possible in principle). Faces seen edge-on are left out, and so are back faces of a closed
/// scene (hidden anyway). With edges on, each polygon is outlined, so that the nearer faces paint over the
/// hidden edges: what remains visible are the visible edges. `options.smooth` is ignored (SVG fills are
/// flat). O(size log size).
void write_svg(const RenderScene& scene, const Camera& camera, const RenderOptions& options,
               std::ostream& out);

/// The same to the file `path`, atomically (or staged in `batch`). Throws IoError naming `path`.
void write_svg(const RenderScene& scene, const Camera& camera, const RenderOptions& options,
               const std::filesystem::path& path, FileBatch* batch = nullptr);

}  // namespace dlfl
