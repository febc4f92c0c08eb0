"""Running the oracle scripts with both implementations and comparing results.

Used by tests/python/test_opensees_oracle.py and benchmarks/opensees_oracle.py.

Numbers are compared entry by entry (an entry is one key of a script's result
dict: a number, a list, a list of lists) against the entry's scale, the
largest magnitude in the OpenSeesPy value: |a - b| <= rtol * scale. Round-off
noise (1e-13 where the other side has 0) is judged against the entry's scale,
not its own size. Integers (iteration counts, return codes, tags) and strings
must be equal; recorder files are compared line by line and token by token.
"""
import fnmatch
import importlib
import json
import math
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_ORACLE_PYTHON = "/work/oracle-venv/bin/python"

# Relative tolerance (against the entry's scale) by key pattern; the first
# matching pattern wins. Linear answers: 1e-8. Converged nonlinear answers
# (tests at 1e-12): also 1e-8. Iteration norms: the last norms of a step are
# round-off, so they are compared against the step's first norm.
TOLERANCES = (
    ("*testNorm*", 1e-6),
    # Penalty constraints (alpha 1e12) converged to NormDispIncr 1e-9: the
    # conditioning leaves ~1e-8 of round-off in the converged state.
    ("Penalty.*", 1e-6),
    # beam_contact: the friction and the beam-node forces part at second order in the slip over the
    # segment ((0.5 mm / 2 m)^2 ~ 6e-8), the friction directions being taken on different
    # configurations; the pull's load factor (global equilibrium) agrees to 1e-13.
    ("pull*.frictionforce", 1e-7),
    ("pull*.master*", 1e-7),
    ("penalty.pull*.frictionforce", 1e-7),
    ("penalty.pull*.master*", 1e-7),
    # time_series: series values are closed forms evaluated at the same times.
    ("ts.*", 1e-12),
    # solid_footing: 25 plastic steps of J2 soil; OpenSeesPy's J2 return stops ~5e-9 short of the exact
    # stress (its local tolerance), which the path carries to ~1e-7 in the displacements.
    ("footing.*", 2e-7),
    # sensitivity_2d: BeamSolid differentiates the geometry (section depth, a node's coordinate) by
    # central differences of 1e-6 relative steps, which leaves ~5e-9 of the exact derivative.
    ("sens.*", 5e-8),
    ("*", 1e-8),
)


# (script, key pattern) -> why BeamSolid differs on purpose.
KNOWN_DIFFERENCES = {
    ("drift_recorders", "drift.file"):
        "recorder('Drift'): OpenSeesPy 3.7.1 misparses its arguments (the documented example with '-time' first and "
        "two pairs fails, 'failed to get dof'; here, one pair with '-time' last, it writes one column of zeros, and in "
        "other probes the drift of a pair other than the one given); BeamSolid's file equals (u_j - u_i)/|dY| of the pair given, which both sides compute from nodeDisp "
        "(drift.fromNodeDisp agrees)",
    ("generalized_alpha", "[bcd].*"):
        "integrator('GeneralizedAlpha', alphaM, alphaF) with alphaM != 1: OpenSeesPy 3.7.1's converged states satisfy "
        "the equation of motion with the inertia of A_n+1 (alphaM left out of the residual; checked on a linear SDOF) "
        "while its tangent carries alphaM M, so Newton takes 8-15 iterations on a linear system; BeamSolid uses "
        "M ((1 - alphaM) A_n + alphaM A_n+1) in both (Chung and Hulbert), 2 iterations, and agrees with an independent "
        "recurrence (test_generalized_alpha). alphaM = 1 (case a) agrees with OpenSeesPy",
    ("beam_integrations_more", "CompositeSimpson11.*"):
        "beamIntegration('CompositeSimpson', tag, secTag, 5): OpenSeesPy 3.7.1 places the points at 0, 1/3, 2/3, 1, 1 "
        "with weights 1/9, 4/9, 2/9, 4/9, 1/9 (N = 7 puts one beyond the element, N = 4 gives garbage); BeamSolid "
        "uses composite Simpson on N - 1 equal intervals (0, 1/4, ..., 1; weights h/3 (1, 4, 2, 4, 1)). N = 3 agrees",
    ("convergence_tests", "*.and.max.*"):
        "test('NormDispAndUnbalance', tolIncr, tolR, iter, pFlag, nType): OpenSeesPy 3.7.1 gives the 2-norm numbers "
        "whatever nType is (its parser misreads the optional arguments: with maxIncr given it takes nType as iter); "
        "BeamSolid uses the documented nType (0 max norm here)",
    ("convergence_tests", "*.and.1norm.*"):
        "see *.and.max.*: nType 1 (1-norm) in BeamSolid, the 2-norm in OpenSeesPy 3.7.1",
    ("ground_motion", "uniform.accel.*Rho.nodeUnbalance"):
        "UniformExcitation: BeamSolid applies an element mass's inertia load -M_e r a_g as nodal loads "
        "(nodeUnbalance shows it); OpenSees keeps it inside the element. Displacements and reactions agree",
    ("shear_sections_3d", "*.point z.*"):
        "forceBeamColumn (3D) with a shear section under eleLoad beamPoint with Pz: OpenSeesPy 3.7.1 gives the "
        "section shear Vz of the load the sign opposite to dMy/dx (Vz = -Pz (L - a)/L before the load, where "
        "equilibrium of the simply supported basic system gives +Pz (L - a)/L), so a doubly symmetric cantilever "
        "deflects 0.003857 under Pz = 1 and 0.003510 under Py = 1 (Lobatto 5, a = 0.35 L); BeamSolid uses "
        "V = dM/dx in both planes (equal deflections, test_shear_sections_3d). Pz = 0 (point y) and beamUniform "
        "agree with OpenSeesPy",
    ("command_behaviour", "eleResponse unknown"):
        "BeamSolid raises OpenSeesError naming the element and the response; OpenSeesPy returns []",
    ("command_behaviour", "eleResponse missing element"):
        "BeamSolid raises OpenSeesError (element does not exist); OpenSeesPy returns []",
    ("command_behaviour", "sp Plain: *"):
        "constraints('Plain') in OpenSees ignores the value of an sp (warns, imposes 0); "
        "BeamSolid's Plain handler imposes it (docs/commands.md)",
    ("response_names", "stdBrick st*"):
        "stdBrick stresses/strains: BeamSolid suffixes the Gauss point (sigma11_1 ... sigma13_8) so that "
        "sidecar columns are unique; OpenSees repeats sigma11 ... sigma13 eight times",
    ("response_names", "truss3 localForce"):
        "OpenSees' truss localForce recorder writes 2*ndf values but no ResponseType names",
    ("command_behaviour", "load with * values"):
        "OpenSees accepts a load with the wrong number of values silently; BeamSolid raises naming the node's ndf",
    ("command_behaviour", "remove sp of nothing"):
        "OpenSees ignores remove('sp') of a dof without sp; BeamSolid raises",
    ("command_behaviour", "remove sp of a pattern: next step"):
        "remove('sp', node, dof) in OpenSees removes only a fix/domain sp; BeamSolid also removes the sp "
        "a load pattern holds (Domain::removeSP)",
    ("command_behaviour", "remove sp of a fix: next step"):
        "singular after removing a fix: OpenSees analyze returns -1 (set-up failed), BeamSolid -3 (algorithm)",
    ("zerolength_contact", "stickslip.slide.step*.force"):
        "zeroLengthContact3D sliding: BeamSolid keeps the friction force at mu N + c (return map, the documented "
        "Mohr-Coulomb law); OpenSeesPy's drops to Kt times the slip past a stick point moved to the step's "
        "position (0 on the step that first slides: a sawtooth)",
    ("beam_contact", "penalty.p*.force"):
        "BeamContact3Dp force: BeamSolid gives the contact force on the soil node (normal plus friction, as "
        "BeamContact3D's force); OpenSeesPy 3.7.1's BeamContact3Dp returns [0, N L / 8, 0] here, the size of "
        "a beam node's contact moment (whose mastermoment agrees with ours), not a force on the soil node",
    ("beam_contact", "*end?.masterforce"):
        "BeamEndContact3D(p) masterforce: BeamSolid's tip node also carries the moment r x F of a soil node off "
        "the face centre (consistent with the face turning with the tip's rotation); OpenSeesPy reports the "
        "force with zero moments. Forces, displacements and iteration counts agree",
    ("zerolength_contact", "dir?.recontact.step0.force"):
        "zeroLengthContact3D closing again after opening: BeamSolid's friction restarts from the tangential "
        "position at the opening (no force carried through a gap); OpenSeesPy keeps the old stick point",
    ("corotational_2d", "offsets.*"):
        "geomTransf Corotational 2D with -jntOffset: BeamSolid's offsets are rigid arms that turn with their "
        "node (exact: a rigid rotation gives no force); OpenSeesPy 3.7.1 does not turn them: 1 rad of rigid "
        "rotation strains its member (axial deformation that of a linearised arm theta Z x d), and its Newton "
        "converges linearly (11-12 iterations a step here against BeamSolid's 4-5)",
    ("damping_regions", "bar.corotTruss.*"):
        "corotTruss with a Viscous material: the same answers to the convergence tolerance (1e-10 on the "
        "increment); BeamSolid's dynamic tangent holds the bar's consistent damping tangent A eta / L0 e e^T "
        "(3 and 6 Newton iterations a step at alpha 1 and 0.5), OpenSeesPy 3.7.1 converges more slowly (7 and "
        "14)",
    ("solid_elements", "bbarQuad.*.ele*.st*"):
        "bbarQuad stresses/strains: OpenSeesPy 3.7.1 writes the 33 component twice per Gauss point (11 22 33 33) "
        "where its material holds 11 22 33 12; BeamSolid writes 11 22 33 12 (the first three agree, and so do "
        "the 'material' k 'stress'/'strain' responses)",
    ("solid_elements", "SSP*.distorted.[de]*"):
        "SSPquad/SSPbrick on non-rectangular elements: the hourglass stiffness differs (docs/solid_elements.md: "
        "ours is the published assumed strain (quad) and Puso's enhanced strain in the natural basis (brick), "
        "OpenSees' differs and is not invariant under rotation); 0.1-0.3 % in displacements, 0.3-1.3 % in "
        "element forces and stresses, 1.8 % in the SSPquad frequencies here. Regular meshes and the patch "
        "test on these meshes agree to 1e-14",
    ("solid_footing", "footing.bbarQuad.edge.stresses"):
        "bbarQuad stresses: OpenSeesPy 3.7.1 writes 11 22 33 33 per Gauss point (see solid_elements)",
    ("solid_elements", "SSPquad.*.distorted.sw.disp"):
        "see SSP*.distorted.[de]*: the self-weight stage on the distorted mesh",
    ("solid_elements", "SSPbrick.distorted.reactionSum"):
        "SSPbrick body force on a distorted element: OpenSees' nodal shares (the weights of its lumped mass) "
        "do not sum to the element volume (6e-8 of the load here); BeamSolid's integral(N_a dV) do",
    ("example3_cantilever", "fiber02.push.section5"):
        "forceBeamColumn's state at the last step: OpenSees' free-end section forces are off b q by up to 1e-3 "
        "(5e-7 of the axial force), BeamSolid's equal b q to round-off. Not traced to the update; the likely cause "
        "is OpenSees' element fall-back past the tangent and initial-flexibility attempts, not reproduced. Every "
        "step's load factor, displacement and iteration count, the base section and the basic forces agree to 1e-8",
    ("mixed_beam_column", "2d.Linear"):
        "forceBeamColumn (which mixedBeamColumn is, in both programs here): at the one step where fibers yield "
        "between Newton iterations (step 15 of 25) OpenSeesPy takes 3 iterations, BeamSolid 2, at any test "
        "tolerance from 1e-10 to 1e-12; the element-level iteration differs (see example3_cantilever). The load "
        "factors, displacements and local forces of every step agree to 1e-8, the other steps' iteration counts "
        "exactly",
    ("modal_damping", "column.hht"):
        "modalDamping under HHT: BeamSolid evaluates the modal damping force at the alpha-state velocity, as "
        "it does Rayleigh damping; OpenSeesPy 3.7.1 gives 4e-4 relative different displacements from the first "
        "step on (Newmark runs agree to 1e-8 with iteration counts)",
}


def known_reason(script, key):
    """Why (script, key) differs on purpose, or None."""
    for (s, pattern), reason in KNOWN_DIFFERENCES.items():
        if s == script and fnmatch.fnmatchcase(key, pattern):
            return reason
    return None


def tolerance_for(key):
    for pattern, rtol in TOLERANCES:
        if fnmatch.fnmatchcase(key, pattern):
            return rtol
    return 1e-8


# The sanitizer run (`make sanitize`) preloads the ASan/UBSan runtimes into every
# child. OpenSeesPy is not our code and not instrumented: its own allocator
# habits would be reported as ours, so the oracle runs without them.
SANITIZER_VARIABLES = ("LD_PRELOAD", "ASAN_OPTIONS", "UBSAN_OPTIONS", "PYTHONMALLOC")


def oracle_env():
    """This process's environment without the sanitizer runtime, for the OpenSeesPy interpreter."""
    return {k: v for k, v in os.environ.items() if k not in SANITIZER_VARIABLES}


def find_oracle_python():
    """A Python where `import openseespy.opensees` works, or None."""
    candidates = [os.environ.get("BEAMSOLID_ORACLE_PYTHON"), DEFAULT_ORACLE_PYTHON]
    for python in candidates:
        if not python or not os.path.exists(python):
            continue
        try:
            probe = subprocess.run([python, "-c", "import openseespy.opensees"], capture_output=True, timeout=120,
                                   env=oracle_env())
        except (OSError, subprocess.TimeoutExpired):
            continue
        if probe.returncode == 0:
            return python
    return None


def run_opensees(python, names, workdir):
    """Results of the scripts under OpenSeesPy, run in a subprocess."""
    output = os.path.join(workdir, "opensees_results.json")
    os.makedirs(workdir, exist_ok=True)
    proc = subprocess.run(
        [python, os.path.join(HERE, "oracle_runner.py"), os.path.join(workdir, "opensees"), output, *names],
        capture_output=True, text=True, timeout=900, env=oracle_env(),
    )
    try:
        with open(output) as f:
            results = json.load(f)
    except (OSError, ValueError):
        results = {}
    for name in names:
        if name not in results:
            results[name] = {"__error__": f"OpenSeesPy run ended (code {proc.returncode}) before this script:\n"
                                           + proc.stderr[-3000:]}
    return results


def run_beamsolid(names, workdir):
    """Results of the scripts under beamsolid.opensees, in this process."""
    import traceback

    import beamsolid.opensees as ops

    if HERE not in sys.path:
        sys.path.insert(0, HERE)
    results = {}
    here = os.getcwd()
    for name in names:
        cwd = os.path.join(workdir, "beamsolid", name)
        os.makedirs(cwd, exist_ok=True)
        os.chdir(cwd)
        try:
            results[name] = importlib.import_module(name).run(ops)
        except Exception:  # noqa: BLE001 - reported by the comparison
            results[name] = {"__error__": traceback.format_exc()}
        finally:
            os.chdir(here)
            try:
                ops.wipe()
            except Exception:  # noqa: BLE001
                pass
        # JSON round trip: both sides are compared in the same form.
        results[name] = json.loads(json.dumps(results[name]))
    return results


# ---------------------------------------------------------------- comparison

class Outcome:
    """The comparison of one entry: ok, the largest relative difference, a note,
    and a kind: "same", "differs", or one of the two documented policies for
    response names: "raises" (BeamSolid raises where OpenSeesPy returns []
    for a name it does not know) and "extra" (BeamSolid answers a name
    OpenSeesPy does not know, e.g. a plural/singular alias)."""

    def __init__(self, ok, rel=0.0, note="", kind=None):
        self.ok, self.rel, self.note = ok, rel, note
        self.kind = kind or ("same" if ok else "differs")

    def __repr__(self):
        return f"Outcome({self.kind}, rel={self.rel:.3g}, note={self.note!r})"


def _flatten(value):
    if isinstance(value, list):
        for v in value:
            yield from _flatten(v)
    else:
        yield value


def _shape(value):
    if isinstance(value, list):
        return [_shape(v) for v in value]
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "int"
    if isinstance(value, float):
        return "float"
    return type(value).__name__


def _is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def compare_values(key, bs, os_value):
    """Compares one entry; os_value (OpenSeesPy) is the reference."""
    if isinstance(os_value, dict) or isinstance(bs, dict):
        if not (isinstance(os_value, dict) and isinstance(bs, dict)) or set(os_value) != set(bs):
            return Outcome(False, math.inf, f"fields differ: BeamSolid {_brief(bs)} vs OpenSees {_brief(os_value)}")
        parts = {k: compare_values(f"{key}.{k}", bs[k], os_value[k]) for k in sorted(os_value)}
        bad = [f"{k}: {o.note}" for k, o in parts.items() if not o.ok]
        return Outcome(not bad, max(o.rel for o in parts.values()), "; ".join(bad))
    if os_value == "[]" and bs == "error":
        return Outcome(True, 0.0, "OpenSeesPy returns [], BeamSolid raises", "raises")
    if os_value == "[]" and isinstance(bs, list):
        return Outcome(True, 0.0, f"only BeamSolid knows this name ({len(bs)} values)", "extra")
    if isinstance(os_value, str) and isinstance(bs, str):
        if key.startswith("file:") or key.endswith(".out") or ".recorder." in key:
            return compare_recorder_text(bs, os_value)
        return Outcome(bs == os_value, 0.0, "" if bs == os_value else f"{bs!r} != {os_value!r}")
    if _shape(bs) != _shape(os_value):
        # Integers are exact; 1 vs 1.0 is a type difference worth reporting.
        return Outcome(False, math.inf, f"shape/type differs: BeamSolid {_brief(bs)} vs OpenSees {_brief(os_value)}")
    flat_b, flat_o = list(_flatten(bs)), list(_flatten(os_value))
    scale = max((abs(v) for v in flat_o if _is_number(v)), default=0.0)
    rtol = tolerance_for(key)
    worst = 0.0
    if "testNorm" in key and all(isinstance(v, float) for v in flat_o):
        # Iteration norms fall by orders of magnitude within a step: each is
        # compared with its own size, down to a floor of 1e-9 of the largest
        # norm of the entry, below which norms are round-off.
        floor = 1e-9 * scale
        for b, o in zip(flat_b, flat_o):
            err = abs(b - o) / (max(abs(b), abs(o)) + floor / rtol) if b != o else 0.0
            worst = max(worst, err)
        return Outcome(worst <= rtol, worst, "" if worst <= rtol else f"norms differ by {worst:.3g} relative")
    for b, o in zip(flat_b, flat_o):
        if isinstance(o, int) and not isinstance(o, bool) and isinstance(b, int):
            if b != o:
                return Outcome(False, math.inf, f"integers differ: BeamSolid {_brief(bs)} vs OpenSees {_brief(os_value)}")
        elif _is_number(o):
            worst = max(worst, _rel(b, o, scale))
        elif b != o:
            return Outcome(False, math.inf, f"{b!r} != {o!r}")
    ok = worst <= rtol
    return Outcome(ok, worst, "" if ok else f"relative difference {worst:.3g} > {rtol:g}")


def _rel(b, o, scale):
    if b == o:
        return 0.0
    if not (math.isfinite(b) and math.isfinite(o)):
        return math.inf
    if scale == 0.0:
        return math.inf
    return abs(b - o) / scale


def _brief(v, n=160):
    s = json.dumps(v)
    return s if len(s) <= n else s[: n - 3] + "..."


_NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^[-+]?(inf|nan)$")


def compare_recorder_text(bs, os_text, rtol=2e-5):
    """Recorder files: same lines and tokens; numbers equal to the printed
    precision (relative to the line's largest value), and counts of
    byte-identical lines and tokens in the note."""
    b_lines, o_lines = bs.splitlines(keepends=True), os_text.splitlines(keepends=True)
    if len(b_lines) != len(o_lines):
        return Outcome(False, math.inf, f"{len(b_lines)} lines vs {len(o_lines)} in OpenSees")
    same_lines = same_tokens = tokens = 0
    worst = 0.0
    for b_line, o_line in zip(b_lines, o_lines):
        if b_line == o_line:
            same_lines += 1
        b_tok, o_tok = b_line.split(), o_line.split()
        if len(b_tok) != len(o_tok):
            return Outcome(False, math.inf, f"line {o_lines.index(o_line) + 1}: {len(b_tok)} values vs {len(o_tok)}")
        if _layout(b_line) != _layout(o_line):
            return Outcome(False, math.inf, f"delimiters differ: {b_line[:60]!r} vs {o_line[:60]!r}")
        nums = [float(t) for t in o_tok if _NUMBER.match(t)]
        scale = max((abs(v) for v in nums), default=0.0)
        for bt, ot in zip(b_tok, o_tok):
            tokens += 1
            if bt == ot:
                same_tokens += 1
                continue
            if not (_NUMBER.match(bt) and _NUMBER.match(ot)):
                return Outcome(False, math.inf, f"token {bt!r} vs {ot!r}")
            worst = max(worst, _rel(float(bt), float(ot), scale))
    ok = worst <= rtol
    note = f"{same_lines}/{len(o_lines)} lines and {same_tokens}/{tokens} values byte-identical"
    if not ok:
        note = f"values differ by {worst:.3g} of the line scale; " + note
    return Outcome(ok, worst, note)


def _layout(line):
    """The line with every token replaced by 'x': delimiters and line end."""
    return re.sub(r"[^ \t,\n\r]+", "x", line)


def compare_script(bs_results, os_results):
    """{key: Outcome} for every key of either side (missing keys fail)."""
    outcomes = {}
    for key in sorted(set(bs_results) | set(os_results)):
        if key == "__error__":
            outcomes[key] = Outcome(False, math.inf, "script raised: " + (bs_results.get(key) or os_results.get(key))[-600:])
        elif key not in os_results:
            outcomes[key] = Outcome(False, math.inf, "only BeamSolid has this entry")
        elif key not in bs_results:
            outcomes[key] = Outcome(False, math.inf, "only OpenSees has this entry")
        else:
            outcomes[key] = compare_values(key, bs_results[key], os_results[key])
    return outcomes
