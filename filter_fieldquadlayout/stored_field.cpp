#include "stored_field.h"

#include "step_common.h"

namespace fcql_meshlab {

bool hasStoredField(const CMeshO& cm) {
  if (!hasFaceField(cm)) return false;
  for (const CFaceO& f : cm.face)
    if (!f.IsD() && f.cPD1().SquaredNorm() > 0) return true;
  return false;
}

StoredField readStoredField(const CMeshO& cm) {
  if (!hasStoredField(cm)) throw fcql::FieldError(kNoFieldMessage);
  const auto start = Clock::now();
  StoredField s;
  s.converted = toSurfaceMesh(cm);
  s.field = readFaceField(cm, s.converted);
  s.analysis = fcql::analyzeField(s.converted.mesh, s.field);
  s.seconds = secondsSince(start);
  return s;
}

}  // namespace fcql_meshlab
