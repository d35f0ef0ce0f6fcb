"""hexc_material: one hexc material (or scene) compiled in one Bazel action; hexc_outputs: the files each writes,
listed by hexc before the build (docs/build-integration.md, "Bazel")."""

# hexc's --targets names and the extensions of the files they write (<name>.frag.<extension>), and the targets it
# writes when given none (tests/backends/target_table_test.cpp checks both against hexc's target table).
_EXTENSIONS = {"spirv": "spv", "hlsl": "hlsl", "glsl": "glsl", "msl": "metal", "wgsl": "wgsl"}
_DEFAULT_TARGETS = ["spirv", "hlsl", "glsl", "msl"]

# Runs hexc ($1, with the arguments after $3), then checks that the files it wrote, the targets of its depfile ($2),
# are the declared ones ($3): Bazel would drop any other without a word, and a shader would miss its table.
_CHECKED_RUN = """
hexc=$1 depfile=$2 declared=$3
shift 3
"$hexc" "$@" || exit
written=$(sed -n '1s/: .*//p' "$depfile" | tr ' ' '\\n' | LC_ALL=C sort | tr '\\n' ' ')
[ "$written" = "$declared " ] && exit 0
echo "hexc_material: hexc wrote [$written] but the rule declares [$declared]: give hexc_material the outs" \\
  "hexc_outputs lists with the same options" >&2
exit 1
"""

# The names hexc keeps a stamp for: one per manifest "<name>.manifest.json" (a material, or a scene's variant).
def _stamped(outs):
    return [f[:-len(".manifest.json")] for f in outs if f.endswith(".manifest.json")]

def _hexc_material_impl(ctx):
    name = ctx.attr.material_name or ctx.label.name
    for target in ctx.attr.targets:
        if target not in _EXTENSIONS:
            fail("unknown target `%s`; expected one of %s" % (target, ", ".join(_EXTENSIONS.keys())), "targets")
    if ctx.attr.outs:
        shaders = [ctx.actions.declare_file(f) for f in ctx.attr.outs]
    else:
        shaders = [ctx.actions.declare_file(name + ".manifest.json")]
        shaders += [ctx.actions.declare_file("%s.frag.%s" % (name, _EXTENSIONS[t])) for t in ctx.attr.targets]
        if ctx.attr.vertex:
            shaders += [ctx.actions.declare_file("%s.vert.%s" % (name, _EXTENSIONS[t])) for t in ctx.attr.targets]

    # hexc always writes its stamp beside the outputs. It is declared, so the action leaves no undeclared file
    # behind; --force, because Bazel, not the stamp, decides when the action runs; --no-cache, because Bazel's own
    # action cache serves that purpose and an action reads nothing undeclared.
    stamps = [ctx.actions.declare_file("." + n + ".hexc-stamp") for n in _stamped(ctx.attr.outs) or [name]]
    depfile = ctx.actions.declare_file("." + ctx.label.name + ".hexc.d")

    args = ctx.actions.args()
    args.add(ctx.file.material)
    args.add("-o", shaders[0].dirname)
    args.add_joined("--targets", ctx.attr.targets, join_with = ",")
    args.add_all(["--force", "--no-cache", "-q", "--depfile", depfile])
    if ctx.attr.vertex:
        args.add("--vertex")
    args.add_all(ctx.attr.options)
    ctx.actions.run_shell(
        command = _CHECKED_RUN,
        arguments = [ctx.executable.hexc.path, depfile.path, " ".join(sorted([f.path for f in shaders])), args],
        tools = [ctx.executable.hexc],
        inputs = [ctx.file.material] + ctx.files.textures + ctx.files.templates,
        outputs = shaders + stamps + [depfile],
        mnemonic = "HexcMaterial",
        progress_message = "hexc: compiling " + name,
    )
    return [DefaultInfo(files = depset(shaders))]

hexc_material = rule(
    implementation = _hexc_material_impl,
    doc = "Compiles one material (or scene) with hexc in one action; its files are `outs` (from hexc_outputs), " +
          "or by default <name>.manifest.json and <name>.frag.<extension> (those of `targets`).",
    attrs = {
        "material": attr.label(
            allow_single_file = [".json", ".mtlx"],
            mandatory = True,
            doc = "The material file: JSON, or a MaterialX document holding one material; or a scene, whose " +
                  "material files go in `textures` with the textures.",
        ),
        "outs": attr.string_list(
            doc = "The files hexc writes, as hexc_outputs lists them (HEXC_OUTPUTS[\"<material path>\"]): " +
                  "histogram tables, packed textures, a scene's variants and index included. Default: " +
                  "<name>.manifest.json and the shaders of `targets` (and `vertex`).",
        ),
        "material_name": attr.string(
            doc = "The material's \"name\", which names the outputs; default: this target's name.",
        ),
        "vertex": attr.bool(
            doc = "Also write the pass-through vertex stage <name>.vert.* (hexc --vertex; not in `options`, " +
                  "whose outputs the rule would not declare).",
        ),
        "textures": attr.label_list(
            allow_files = True,
            doc = "Every texture the material names. hexc finds them relative to the material file, as " +
                  "their workspace paths place them; one left out fails the build in a sandbox.",
        ),
        "templates": attr.label_list(
            allow_files = [".glsl"],
            doc = "A template the material names by path, or one given with --template in `options`.",
        ),
        "hexc": attr.label(
            executable = True,
            cfg = "exec",
            allow_single_file = True,
            mandatory = True,
            doc = "The hexc executable, e.g. @hexc//:bin/hexc.",
        ),
        "targets": attr.string_list(
            default = _DEFAULT_TARGETS,
            doc = "Subset of hexc's --targets names; default: hexc's default.",
        ),
        "options": attr.string_list(
            doc = "More hexc options, as written, e.g. [\"--bake\", \"--hlsl-sm\", \"60\"].",
        ),
    },
)

def _hexc_outputs_impl(rctx):
    hexc = rctx.path(rctx.attr.hexc)

    # Each file named is read through its label, so Bazel fetches this repository again when one changes.
    for f in rctx.attr.srcs:
        rctx.path(f)
    lines = []
    for material, options in rctx.attr.materials.items():
        path = material.name if not material.package else material.package + "/" + material.name
        command = [hexc, rctx.path(material), "-o", "out", "--list-outputs"] + [o for o in options.split(" ") if o]
        result = rctx.execute(command)
        if result.return_code != 0:
            fail("hexc --list-outputs %s:\n%s" % (path, result.stderr))
        outs = [f[len("out/"):] for f in json.decode(result.stdout)["outputs"]]
        lines.append("    %s: %s," % (repr(path), repr(outs)))
    rctx.file("BUILD", "")
    rctx.file("outputs.bzl", "# Written by hexc_outputs.\nHEXC_OUTPUTS = {\n" + "\n".join(sorted(lines)) + "\n}\n")

hexc_outputs = repository_rule(
    implementation = _hexc_outputs_impl,
    doc = "Runs `hexc --list-outputs` on each material when Bazel loads the workspace and writes " +
          "@<name>//:outputs.bzl, whose HEXC_OUTPUTS maps each material's workspace path to the files hexc " +
          "writes for it, for hexc_material's `outs`. Listed again when a material or a file of `srcs` changes.",
    attrs = {
        "hexc": attr.label(mandatory = True, allow_single_file = True, doc = "The hexc executable."),
        "materials": attr.label_keyed_string_dict(
            allow_files = True,
            mandatory = True,
            doc = "Each material (or scene) file, with the hexc options its hexc_material passes " +
                  "(`--targets`, `--vertex`, `options`), space-separated.",
        ),
        "srcs": attr.label_list(
            allow_files = True,
            doc = "The files the lists depend on besides the materials: a scene's material files, a template, " +
                  "a packing material's textures (their pixels decide what packs).",
        ),
    },
)
