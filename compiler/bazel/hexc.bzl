"""hexc_material: one hexc material compiled in one Bazel action (docs/build-integration.md, "Bazel")."""

# hexc's --targets names and the extensions of the files they write (<name>.frag.<extension>).
_EXTENSIONS = {"spirv": "spv", "hlsl": "hlsl", "glsl": "glsl", "msl": "metal"}

def _hexc_material_impl(ctx):
    name = ctx.attr.material_name or ctx.label.name
    for target in ctx.attr.targets:
        if target not in _EXTENSIONS:
            fail("unknown target `%s`; expected spirv, hlsl, glsl or msl" % target, "targets")
    shaders = [ctx.actions.declare_file(name + ".manifest.json")]
    shaders += [ctx.actions.declare_file("%s.frag.%s" % (name, _EXTENSIONS[t])) for t in ctx.attr.targets]
    if ctx.attr.vertex:
        shaders += [ctx.actions.declare_file("%s.vert.%s" % (name, _EXTENSIONS[t])) for t in ctx.attr.targets]

    # hexc always writes its stamp beside the outputs. It is declared, so the action leaves no undeclared file
    # behind; --force, because Bazel, not the stamp, decides when the action runs; --no-cache, because Bazel's own
    # action cache serves that purpose and an action reads nothing undeclared.
    stamp = ctx.actions.declare_file("." + name + ".hexc-stamp")

    args = ctx.actions.args()
    args.add(ctx.file.material)
    args.add("-o", shaders[0].dirname)
    args.add_joined("--targets", ctx.attr.targets, join_with = ",")
    args.add_all(["--force", "--no-cache", "-q"])
    if ctx.attr.vertex:
        args.add("--vertex")
    args.add_all(ctx.attr.options)
    ctx.actions.run(
        executable = ctx.executable.hexc,
        arguments = [args],
        inputs = [ctx.file.material] + ctx.files.textures + ctx.files.templates,
        outputs = shaders + [stamp],
        mnemonic = "HexcMaterial",
        progress_message = "hexc: compiling " + name,
    )
    return [DefaultInfo(files = depset(shaders))]

hexc_material = rule(
    implementation = _hexc_material_impl,
    doc = "Compiles one material with hexc: <name>.manifest.json and <name>.frag.{spv,hlsl,glsl,metal} " +
          "(those of `targets`).",
    attrs = {
        "material": attr.label(
            allow_single_file = [".json", ".mtlx"],
            mandatory = True,
            doc = "The material file: JSON, or a MaterialX document holding one material.",
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
            default = ["spirv", "hlsl", "glsl", "msl"],
            doc = "Subset of spirv, hlsl, glsl, msl (hexc's --targets); default: all four, as hexc's.",
        ),
        "options": attr.string_list(
            doc = "More hexc options, as written, e.g. [\"--bake\", \"--hlsl-sm\", \"60\"].",
        ),
    },
)
