"""The figures record of a run as the three front ends give it, compared key by key.

fcql's stats.json nests the dotted names; the MeshLab log's "Figures: {...}" line and
pymeshlab's dict keep them flat. Used by figures_agree.sh and pymeshlab_real.py.
"""

# A computed field agrees between processes to rounding only (the CLI and MeshLab's process
# give the sparse solves the same input but not bit for bit the same output), and these quality
# measures look the field up per face at each quad's centre: a quad whose centre moves across a
# face edge by rounding changes them by a step; the sides' parameters, solved for all patches at
# once, pass the rounding on to every quad's shape (the mean scaled Jacobian); a vertex moved onto
# a tip the quads missed (quad.snapped_vertices) goes to a sample point of the distance measure,
# the farthest one found, which passes it on to its quads' shape (the kitten's least scaled
# Jacobian: 0.139984 in the CLI, 0.139973 through pymeshlab). They are compared to within that;
# every count, flag, text and other real exactly (to the 6 digits stats.json keeps).
ROUNDING_SENSITIVE = {"quad.mean_misalignment_deg": 0.01, "quad.misaligned_pct": 0.1,
                      "quad.misaligned_faces_pct": 0.1, "quad.hausdorff_bound_rel": 1e-6,
                      "quad.hausdorff_rel": 1e-6, "quad.hausdorff": 1e-5, "quad.mean_scaled_jacobian": 1e-4,
                      "quad.min_scaled_jacobian": 1e-4}


def flat(tree, prefix=""):
    """stats.json's nested objects as dotted keys (an empty object gives no key)."""
    out = {}
    for key, value in tree.items():
        if isinstance(value, dict):
            out.update(flat(value, prefix + key + "."))
        else:
            out[prefix + key] = value
    return out


def compared_keys(reference, other, with_text=True):
    """The keys compared: all but times and the input's name (and text values if not with_text)."""
    return sorted(k for k in set(reference) | set(other)
                  if not k.startswith(("time_s.", "input."))
                  and (with_text or not isinstance(reference.get(k), str)))


def differences(reference, other, names=("fcql run", "other"), with_text=True):
    """Lines naming each key whose values differ."""
    bad = []
    for k in compared_keys(reference, other, with_text):
        a, b = reference.get(k), other.get(k)
        if k in ROUNDING_SENSITIVE:
            same = a is not None and b is not None and abs(a - b) <= ROUNDING_SENSITIVE[k]
        elif isinstance(a, float) or isinstance(b, float):
            same = a is not None and b is not None and abs(a - b) <= 1e-5 * max(abs(a), abs(b), 1e-12)
        else:
            same = a == b
        if not same:
            bad.append("%s: %s %r, %s %r" % (k, names[0], a, names[1], b))
    return bad
