// fcql: field-coherent quad layouts from the command line.
#include "command_line.h"
#include "commands.h"

#include <cstring>
#include <exception>
#include <iostream>
#include <new>

namespace {

const char* kUsage =
    "usage: fcql COMMAND [options]\n"
    "\n"
    "commands:\n"
    "  field MESH|--example NAME [--field F.ffield|F.rosy] [--sharp-angle DEG] [--field-scale 0.02]\n"
    "        --out DIR [--quiet]\n"
    "        read or compute the cross field, find its singularities and separatrix ports;\n"
    "        a computed field sees the surface's curvature at field-scale × the bounding-box\n"
    "        diagonal (0..1; 0: at each vertex, one singularity pair per bump of noise);\n"
    "        writes DIR/field.ffield and DIR/stats.json\n"
    "  trace MESH|--example NAME [field options] [--alpha 20] [--k 10] [--phi 10] [--threads N] --out DIR\n"
    "        build graph G, trace field-coherent separatrices from every port (Dijkstra, k sinks)\n"
    "        and build graph H; writes DIR/candidates.obj, DIR/field.ffield and DIR/stats.json\n"
    "  layout MESH|--example NAME [field and trace options] [--ilp-time-limit 60] [--ilp-stall 50]\n"
    "        [--completion-trials 24] --out DIR\n"
    "        select separatrices (0-1 program, solving cycle, t-junctions, borders), cut the\n"
    "        surface into patches; adds DIR/separatrices.obj and DIR/layout.ply; lp_solve\n"
    "        stops once ilp-stall branch-and-bound nodes bring no better selection (0: never;\n"
    "        counted in nodes, so the same input gives the same layout on any machine); the\n"
    "        time limit is only a safety stop, and the log and stats.json say when it is reached;\n"
    "        where ports are left dangling, up to completion-trials sets of the separatrices in\n"
    "        their way are freed and matched again, each kept only if fewer t-junctions remain\n"
    "        (0: none)\n"
    "  run MESH|--example NAME [all options above] [--scale 0.02 | --target-faces N] [--smooth 5]\n"
    "        [--max-deviation 0.01] [--param field|mean-value] --out DIR\n"
    "        the whole pipeline down to the quad mesh (side-length ILP, patch sampling);\n"
    "        where the quads deviate from the surface by more than max-deviation (share of\n"
    "        the bounding-box diagonal; 0: no check), undoes the smoothing around those\n"
    "        places, then if still needed samples again with smaller quads, up to 4 times;\n"
    "        adds DIR/quad.obj (`quad` is the same command); --param: each patch's grid follows\n"
    "        the cross field inside it (default) or mean-value coordinates (the former map)\n"
    "  render DIR [--view layout|quad|both] [--size 800] [--azimuth 30] [--elevation 20] [--up y] --out FILE.png\n"
    "        draw a PNG of a run's output directory without a display: patches in colour with\n"
    "        separatrices and singularities (layout), the quad mesh with its irregular vertices\n"
    "        (quad), or both side by side\n"
    "\n"
    "MESH is a triangle mesh in OBJ, PLY or OFF. Examples the tool generates itself:\n"
    "  sphere, torus, double_torus, rounded_box, open_cylinder\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
    std::cout << kUsage;
    return argc < 2 ? 2 : 0;
  }
  std::string command = argv[1];
  try {
    if (command == "field") return fcql::fieldCommand(argc, argv);
    if (command == "trace") return fcql::traceCommand(argc, argv);
    if (command == "layout") return fcql::layoutCommand(argc, argv);
    if (command == "quad" || command == "run") return fcql::quadCommand(argc, argv);
    if (command == "render") return fcql::renderCommand(argc, argv);
    std::cerr << "fcql: error: unknown command '" << command << "' (see fcql --help)\n";
    return 2;
  } catch (const fcql::UsageError& e) {
    std::cerr << "fcql: error: " << e.what() << " (see fcql --help)\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "fcql: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "fcql: error: " << e.what() << "\n";
    return 1;
  }
}
