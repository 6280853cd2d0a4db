#pragma once
// The software rasterizer: a scene seen through a camera, as an RGBA image. No display and no GPU.
//
// Faces are filled through a depth buffer at 2 x 2 samples per pixel (the anti-aliasing: each pixel is the
// mean of its four samples), flat or, with `smooth`, with interpolated vertex normals. Polygons are fans of
// triangles whose edge functions are evaluated in fixed point (1/16 sample) with a fill rule that gives
// every sample on a shared edge to exactly one side, so adjacent faces leave no cracks and never overlap;
// a face that is not convex in the picture is filled by the even-odd rule instead. Edges, curves and points
// are drawn last, as strips and discs that pass the depth test when they are no further than the surface
// under them; faces are pushed back by 1.5 samples of their depth slope (a polygon offset), so an edge on
// its own face always passes and one behind another face never does.

#include <dlfl/render/camera.h>
#include <dlfl/render/image.h>
#include <dlfl/render/scene.h>
#include <dlfl/render/shading.h>

namespace dlfl {

/// Renders `scene` at the camera's width x height. O(pixels + size of the scene); allocates only the
/// buffers of the picture (8 bytes per sample) and a few arrays per vertex, nothing per face.
Image render(const RenderScene& scene, const Camera& camera, const RenderOptions& options = {});

}  // namespace dlfl
