// fcql: field-coherent quad layouts from the command line.
#include "command_line.h"
#include "commands.h"

#include <cstring>
#include <exception>
#include <iostream>
#include <new>

namespace {

/// The commands; their options come from the parameter table (vcg_ext/pipeline/parameters.cpp).
std::string usage() {
  using fcql::PipelineStage;
  return std::string(
             "usage: fcql COMMAND [options]\n"
             "\n"
             "commands:\n"
             "  field MESH|--example NAME [field options] --out DIR [--quiet]\n"
             "        read or compute the cross field, find its singularities and separatrix ports;\n"
             "        writes DIR/field.ffield and DIR/stats.json\n"
             "  trace MESH|--example NAME [field and trace options] --out DIR\n"
             "        build graph G, trace field-coherent separatrices from every port (Dijkstra, k sinks)\n"
             "        and build graph H; adds DIR/candidates.obj\n"
             "  layout MESH|--example NAME [field, trace and layout options] --out DIR\n"
             "        select separatrices (0-1 program, solving cycle, completion, t-junctions, borders),\n"
             "        cut the surface into patches; adds DIR/separatrices.obj and DIR/layout.ply\n"
             "  run MESH|--example NAME [all options] --out DIR\n"
             "        the whole pipeline down to the quad mesh (side-length ILP, patch sampling,\n"
             "        smoothing, distance check); adds DIR/quad.obj (`quad` is the same command)\n"
             "  render DIR [--view layout|quad|both] [--size 800] [--azimuth 30] [--elevation 20] [--up y] --out FILE.png\n"
             "        draw a PNG of a run's output directory without a display: patches in colour with\n"
             "        separatrices and singularities (layout), the quad mesh with its irregular vertices\n"
             "        (quad), or both side by side\n"
             "  parameters [--markdown | --mlx STAGE,...]\n"
             "        the options below; --markdown: as the README's tables, with the MeshLab/pymeshlab\n"
             "        names; --mlx field,trace,...: the <Param> lines of a MeshLab script for those stages\n"
             "\n"
             "--quiet (every command): no progress or log lines on stderr, only warnings (\"fcql: warning: ...\",\n"
             "        e.g. quads left folded, ports left dangling) and errors\n"
             "\n"
             "field options:\n") +
         fcql::parametersUsage(PipelineStage::Field) + "\ntrace options:\n" + fcql::parametersUsage(PipelineStage::Trace) +
         "\nlayout options:\n" + fcql::parametersUsage(PipelineStage::Layout) + "\nquad options (run):\n" +
         fcql::parametersUsage(PipelineStage::Quad) +
         "\n"
         "MESH is a triangle mesh in OBJ, PLY or OFF. Examples the tool generates itself:\n"
         "  sphere, torus, double_torus, rounded_box, open_cylinder\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
    std::cout << usage();
    return argc < 2 ? 2 : 0;
  }
  std::string command = argv[1];
  try {
    if (command == "field") return fcql::pipelineCommand(fcql::PipelineStage::Field, argc, argv);
    if (command == "trace") return fcql::pipelineCommand(fcql::PipelineStage::Trace, argc, argv);
    if (command == "layout") return fcql::pipelineCommand(fcql::PipelineStage::Layout, argc, argv);
    if (command == "quad" || command == "run") return fcql::pipelineCommand(fcql::PipelineStage::Quad, argc, argv);
    if (command == "render") return fcql::renderCommand(argc, argv);
    if (command == "parameters") return fcql::parametersCommand(argc, argv);
    std::cerr << "fcql: error: unknown command '" << command << "' (see fcql --help)\n";
    return 2;
  } catch (const fcql::UsageError& e) {
    std::cerr << "fcql: error: " << e.what() << " (see fcql --help)\n";
    return 2;
  } catch (const fcql::ParameterError& e) {
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
