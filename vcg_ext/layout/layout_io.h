// Writing a patch layout: layout.ply (the refined surface with per-face `patch` and colour,
// per-vertex `corner`) and the separatrices as OBJ polylines.
#pragma once

#include "layout/patch_layout.h"

#include <array>
#include <string>

namespace fcql {

/// ASCII PLY text of the layout; faces are coloured by patch (a fixed palette).
std::string patchLayoutToPly(const PatchLayout& layout);

/// OBJ polylines, one `l` per separatrix of the layout (comments say its kind and ports).
std::string separatricesToObj(const Layout& layout);

/// A well-spread colour for patch number i.
std::array<unsigned char, 3> patchColour(int i);

}  // namespace fcql
