#!/usr/bin/env python3
"""What each particle fragment program costs per fragment, counted without a GPU: the shader as
the program cache builds it (its includes inlined, its defines after #version), compiled to
SPIR-V by glslang and optimised by spirv-opt -O, then its operations counted:

  alu      scalar arithmetic operations (a vec3 multiply counts 3, a dot of n components n: a
           multiply and n - 1 multiply-adds); a built-in as the operations it takes (EXT_COST:
           mix 2 a component, normalize of n components 2n + 1, pow 3); an add or subtract of
           a multiply's result used nowhere else is not counted (a GPU compiler fuses the two
           into a multiply-add, as spirv-opt does only for scalars); a negation or an absolute
           value is not counted either, being a free operand modifier on GPUs
  texture  texture reads (samples, fetches, gathers) and size queries (a GPU's texture unit
           answers those too)
  branch   conditional branches and discards

A GPU compiler makes its own code from the same source, so the counts are a yardstick between
versions of a shader, not a GPU's instruction count. They are what a GPU pays per fragment where
its fragment stage is bound by arithmetic.

  python3 scripts/shader_ops.py            the table
  python3 scripts/shader_ops.py --check    fails where a program exceeds its budget below, and
                                           says where one is under it (lower the budget then)

Needs glslangValidator and spirv-opt (Debian: glslang-tools, spirv-tools; scripts/deps.sh).
"""
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
SHADERS = ROOT / "shaders"

# (name, fragment shader, defines as ProgramCache::Key::defines() writes them, budget alu,
# budget texture reads). Soft is built per contrast power: FX_POWER_STEPS = 2 x power.
GATHER = "#extension GL_ARB_texture_gather : require"
PROGRAMS = [
    ("hard", "fs_particles_hard.glsl", [], 11, 1),
    ("hard, quarter res", "fs_particles_hard.glsl", ["FX_LINEAR_DEPTH_TEST", "FX_HALF_RES_DEPTH"], 16, 2),
    ("soft, power 1", "fs_particles_soft.glsl", ["FX_POWER_STEPS 2"], 21, 2),
    ("soft, power 2", "fs_particles_soft.glsl", ["FX_POWER_STEPS 4"], 28, 2),
    ("soft, any power", "fs_particles_soft.glsl", ["FX_GENERAL_POWER"], 31, 2),
    ("soft, power 1, quarter res", "fs_particles_soft.glsl", ["FX_HALF_RES_DEPTH", "FX_POWER_STEPS 2"], 17, 2),
    ("spherical", "fs_particles_spherical.glsl", ["FX_SPHERICAL"], 50, 2),
    ("spherical, quarter res", "fs_particles_spherical.glsl", ["FX_SPHERICAL", "FX_HALF_RES_DEPTH"], 45, 2),
    ("hard, lit", "fs_particles_hard.glsl", ["FX_LIT"], 42, 1),
    ("soft, power 1, lit", "fs_particles_soft.glsl", ["FX_POWER_STEPS 2", "FX_LIT"], 52, 2),
    ("spherical, lit", "fs_particles_spherical.glsl", ["FX_SPHERICAL", "FX_LIT"], 80, 2),
    # Quarter res's fixed passes as a GL 4 context builds them (ProgramCache::Key::defines): the
    # depth downsample (per half-res texel), the composite (per pixel of its tiles; the counts
    # take every side of its branches: a smoke-free pixel stops after the first fetch, one
    # without a depth edge after the gather).
    ("quarter res: downsample", "fs_particles_depth_downsample.glsl", [GATHER, "FX_GATHER"], 40, 1),
    ("quarter res: composite", "fs_particles_composite.glsl", [GATHER, "FX_GATHER"], 96, 5),
    ("mega: composite", "fs_mega_composite.glsl", [GATHER, "FX_GATHER"], 53, 3),
    # The mega blur passes loop over their taps (uTaps each side): the loop's body counts once.
    ("mega: blur", "fs_mega_blur.glsl", [], 48, 4),
    ("mega: blur and shade", "fs_mega_blur.glsl", ["FX_MEGA_SHADE"], 365, 4),
]

ALU = re.compile(r"= Op(F[A-Z]\w*|I[A-Z]\w*|S[A-Z][a-z]*Div|ExtInst|Select|VectorTimesScalar|Dot|Logical\w*|"
                 r"Convert\w+|BitwiseAnd|BitwiseOr|ShiftRightArithmetic|ShiftLeftLogical|Any|All|Not)\b")
# GLSL built-ins that are more than one operation a component: (per component, once).
EXT_COST = {"FMix": (2, 0), "Normalize": (2, 1), "Length": (1, 1), "Distance": (2, 1),
            "Pow": (3, 0), "Exp": (2, 0), "Log": (2, 0), "Cross": (2, 0), "SmoothStep": (5, 0)}
MODIFIER = re.compile(r"= Op(FNegate|SNegate|ExtInst %\w+ %\w+ (FAbs|SAbs))\b")
TEXTURE = re.compile(r"= OpImage(Sample|Fetch|Gather|Query)\w*")
BRANCH = re.compile(r"\bOp(BranchConditional|Kill)\b")


def inline(path):
    """The shader with its #include "file" lines replaced by the files (recursively)."""
    out = []
    for line in path.read_text().splitlines():
        m = re.match(r'\s*#include\s+"([^"]+)"', line)
        out.append(inline(path.parent / m.group(1)) if m else line)
    return "\n".join(out)


def source(fragment, defines):
    lines = inline(SHADERS / fragment).split("\n")
    if not lines[0].startswith("#version"):
        sys.exit(f"shader_ops.py: {fragment}: expected #version on its first line")
    # A define given with its directive (an #extension line) is written as it is.
    return "\n".join([lines[0]] + [d if d.startswith("#") else "#define " + d for d in defines] + lines[1:]) + "\n"


def count(fragment, defines):
    with tempfile.TemporaryDirectory() as work:
        work = pathlib.Path(work)
        (work / "s.frag").write_text(source(fragment, defines))
        for cmd in (["glslangValidator", "-G", "--auto-map-locations", "--auto-map-bindings", "-o",
                     str(work / "s.spv"), str(work / "s.frag")],
                    ["spirv-opt", "-O", str(work / "s.spv"), "-o", str(work / "o.spv")],
                    ["spirv-dis", "-o", str(work / "o.txt"), str(work / "o.spv")]):
            r = subprocess.run(cmd, capture_output=True, text=True)
            if r.returncode != 0:
                sys.exit(f"shader_ops.py: {fragment} {defines}: {cmd[0]} failed:\n{r.stdout}{r.stderr}")
        text = (work / "o.txt").read_text().splitlines()
    width = {}  # type -> components
    typeOf = {}  # value -> its type
    for line in text:
        m = re.match(r"\s*(%\w+) = OpType(Float|Int|Bool)\b", line)
        if m:
            width[m.group(1)] = 1
        m = re.match(r"\s*(%\w+) = OpTypeVector (%\w+) (\d+)", line)
        if m:
            width[m.group(1)] = int(m.group(3))
        m = re.match(r"\s*(%\w+) = Op\w+ (%\w+)", line)
        if m:
            typeOf[m.group(1)] = m.group(2)
    # Multiplies whose result one add or subtract uses, and nothing else: that add is fused.
    products = {m.group(1) for m in (re.match(r"\s*(%\w+) = Op(FMul|VectorTimesScalar) ", line)
                                     for line in text) if m}
    uses = {}
    for line in text:
        for operand in re.findall(r"%\w+", line.split("=", 1)[1] if " = " in line else line):
            uses[operand] = uses.get(operand, 0) + 1
    fused = 0
    for line in text:
        m = re.match(r"\s*%\w+ = Op(FAdd|FSub) (%\w+) (%\w+) (%\w+)", line)
        if m and any(o in products and uses.get(o) == 1 for o in (m.group(3), m.group(4))):
            fused += width.get(m.group(2), 1)
    alu = -fused
    texture = branch = 0
    for line in text:
        if ALU.search(line) and not MODIFIER.search(line):
            m = re.match(r"\s*%\w+ = Op(\w+) (%\w+)(?: (%\w+))?", line)
            ext = re.search(r"= OpExtInst %\w+ %\w+ (\w+) (%\w+)", line)
            if m and m.group(1) == "Dot":
                alu += width.get(typeOf.get(m.group(3)), 1)
            elif ext and ext.group(1) in EXT_COST:
                each, once = EXT_COST[ext.group(1)]
                alu += each * width.get(typeOf.get(ext.group(2)), 1) + once
            else:
                alu += width.get(m.group(2), 1) if m else 1
        if TEXTURE.search(line):
            texture += 1
        if BRANCH.search(line):
            branch += 1
    return alu, texture, branch


def main():
    check = sys.argv[1:] == ["--check"]
    if sys.argv[1:] and not check:
        sys.exit(__doc__)
    print("| program | alu | texture | branch | budget alu, texture |")
    print("|---|---:|---:|---:|---:|")
    over, under = [], []
    for name, fragment, defines, budget_alu, budget_texture in PROGRAMS:
        alu, texture, branch = count(fragment, defines)
        print(f"| {name} | {alu} | {texture} | {branch} | {budget_alu}, {budget_texture} |")
        if alu > budget_alu or texture > budget_texture:
            over.append(f"{name}: {alu} alu, {texture} texture against {budget_alu}, {budget_texture}")
        elif alu < budget_alu or texture < budget_texture:
            under.append(f"{name}: {alu} alu, {texture} texture, under its budget {budget_alu}, {budget_texture}")
    for line in under:
        print(f"shader_ops.py: {line} (lower the budget in scripts/shader_ops.py)")
    for line in over:
        print(f"shader_ops.py: over budget: {line}")
    if check and over:
        sys.exit(1)


if __name__ == "__main__":
    main()
