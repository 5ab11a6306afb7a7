#!/usr/bin/env bash
# Only vcg_ext/solver/ may include lp_solve's headers: the integer programs and the set packing
# are the library's one front end to lp_solve (issue #22). Usage: lp_solve_includes.sh SOURCE_DIR
set -euo pipefail
root=${1:?usage: lp_solve_includes.sh SOURCE_DIR}
cd "$root"
found=$(grep -rEn '^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"](lpsolve/|lp_lib\.h|lp_types\.h|lp_solve)' \
          --include='*.h' --include='*.hpp' --include='*.cpp' --include='*.cc' \
          vcg_ext apps filter_fieldquadlayout tests | grep -v '^vcg_ext/solver/' || true)
if [ -n "$found" ]; then
  echo "lp_solve headers included outside vcg_ext/solver/:" >&2
  echo "$found" >&2
  exit 1
fi
echo "lp_solve headers: only vcg_ext/solver/ includes them"
