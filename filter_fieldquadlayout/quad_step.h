// Filter 4, "Quadrangulate": integer side lengths for the patches of the layout, zero-chain
// splits, and sampling of every patch into a grid of quads (the pipeline's quad stage, as
// `fcql run` runs it).
//
// What is stored: a new layer "quad mesh". MeshLab has no quads, so each quad is two triangles
// whose shared diagonal (the shorter one) is flagged faux on both, which is how MeshLab shows
// and exports polygons. Faces are coloured by the layout patch the quad comes from (with
// "fcql_patch"/"fcql_patch_f"), and the face quality is the quad's scaled Jacobian: the
// minimum over its 4 corners of (e1 x e2) . n / (|e1| |e2|), 1 for a square, <= 0 for a
// folded or concave corner.
#pragma once

#include "meshlab_api.h"

#include "document_layers.h"
#include "filter_parameters.h"
#include "pipeline/quad_stage.h"
#include "step_common.h"

#include <string>
#include <vector>

namespace fcql_meshlab {

constexpr const char* kQuadLayer = "quad mesh";

struct QuadStepResult {
  fcql::QuadStageResult quad;
  std::vector<float> scaledJacobian;  ///< per quad (the face quality of the layer)
  TriangleLayerData layer;
};

/// `mesh` is the input surface (for the bounding-box diagonal), `field` its cross field (each
/// patch is mapped onto its rectangle along it, as `fcql run` does), `layout` its patch layout.
/// Throws std::runtime_error if the layout cannot be quadrangulated (e.g. invalid patches).
QuadStepResult computeQuadStep(const fcql::SurfaceMesh& mesh, const fcql::CrossField& field,
                               const fcql::LayoutStageResult& layout, const fcql::PipelineParameters& params,
                               const Progress& progress);

void storeQuadStep(MeshDocument& md, const QuadStepResult& result);

/// What the step stored, for the log.
std::vector<std::string> describeQuadLayer(const QuadStepResult& result);

}  // namespace fcql_meshlab
