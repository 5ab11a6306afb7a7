#include "layout/separatrix_selection.h"

#include <stdexcept>

namespace fcql {

SelectionResult selectSeparatrices(const SeparatrixGraph& h, const std::vector<char>& portFree, double timeLimitSeconds) {
  SelectionResult out;
  auto free = [&](int p) { return portFree.empty() || (p >= 0 && p < int(portFree.size()) && portFree[p]); };
  // Scale the objective so that coefficients are near 1 whatever the mesh units.
  double meanLength = 0;
  for (const auto& a : h.arcs) meanLength += a.length;
  meanLength = h.arcs.empty() ? 1 : meanLength / h.arcs.size();
  IntegerProgram ip;
  ip.setMaximize(true);
  std::vector<int> variableOf(h.arcs.size(), -1);
  std::vector<int> arcOf;
  for (int i = 0; i < int(h.arcs.size()); ++i) {
    const auto& a = h.arcs[i];
    if (!free(a.portA) || !free(a.portB) || !(a.length > 0)) continue;
    variableOf[i] = ip.addBinary(meanLength / a.length);
    arcOf.push_back(i);
  }
  // Eq. 2: at most one separatrix per port.
  for (int p = 0; p < int(h.arcsAtPort.size()); ++p) {
    std::vector<std::pair<int, double>> terms;
    for (int a : h.arcsAtPort[p])
      if (variableOf[a] >= 0) terms.push_back({variableOf[a], 1.0});
    if (terms.size() > 1) ip.addConstraint(terms, IntegerProgram::Sense::LessEqual, 1.0);
  }
  // Eq. 3: tangential crossings exclude each other.
  for (const auto& pr : h.tangentialPairs) {
    int a = variableOf[pr.first], b = variableOf[pr.second];
    if (a >= 0 && b >= 0) ip.addConstraint({{a, 1.0}, {b, 1.0}}, IntegerProgram::Sense::LessEqual, 1.0);
  }
  out.variables = ip.numVariables();
  out.constraints = ip.numConstraints();
  IntegerProgram::Result r = ip.solve(timeLimitSeconds);
  out.status = r.status;
  out.message = r.message;
  out.seconds = r.seconds;
  if (!r.hasSolution()) throw std::runtime_error("separatrix selection: " + r.message);
  for (int v = 0; v < int(arcOf.size()); ++v)
    if (r.values[v] > 0.5) out.selected.push_back(arcOf[v]);
  return out;
}

}  // namespace fcql
