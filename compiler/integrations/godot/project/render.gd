# Renders each job of job.json in turn: its shader (a hexc package's, or the test's value view of it) on a quad that
# fills the window, its textures bound as the job says, under the job's light if any, with a red marker square that
# Godot draws over the screen's top-left corner (a ColorRect: the image's orientation is checked by it); saves each
# frame as PNG (a job without "out" is only drawn: its shader compiled), then quits. The quad is Godot's own QuadMesh
# (uv (0, 0) at its top-left, v down) unless the job gives "uv": then a mesh with uv [u0, v0] at its top-left corner
# and [u1, v1] at its bottom-right, the tangent frame of QuadMesh (tangent +x, binormal up the screen), and with the
# job's "colors" its vertex colours (top-left, top-right, bottom-left, bottom-right; linear, as stored). Each job's
# start is printed to stderr ("HEXC-JOB n"), so that a shader error, which Godot prints there, names its job.
extends Spatial

const MARKER = 16  # the marker's side in pixels: a sixteenth of the 256-pixel window

var frames = 0
var jobs = []
var done = 0
var scene = null

func _ready():
    var f = File.new()
    f.open("res://job.json", File.READ)
    jobs = parse_json(f.get_as_text())["jobs"]
    f.close()
    var layer = CanvasLayer.new()
    var marker = ColorRect.new()
    marker.color = Color(1, 0, 0)
    marker.rect_position = Vector2(0, 0)
    marker.rect_size = Vector2(MARKER, MARKER)
    layer.add_child(marker)
    add_child(layer)
    start(jobs[0])

func texture(t):
    var image = Image.new()
    if image.load(t["path"]) != OK:
        printerr("HEXC-ERROR cannot load ", t["path"])
    var flags = Texture.FLAG_MIPMAPS | Texture.FLAG_REPEAT | Texture.FLAG_FILTER
    if t["srgb"]:
        flags |= Texture.FLAG_CONVERT_TO_LINEAR
    var result = ImageTexture.new()
    result.create_from_image(image, flags)
    return result

func mesh(uv, colors):
    var arrays = []
    arrays.resize(Mesh.ARRAY_MAX)
    arrays[Mesh.ARRAY_VERTEX] = PoolVector3Array([Vector3(-1, 1, 0), Vector3(1, 1, 0), Vector3(-1, -1, 0), Vector3(1, -1, 0)])
    arrays[Mesh.ARRAY_NORMAL] = PoolVector3Array([Vector3(0, 0, 1), Vector3(0, 0, 1), Vector3(0, 0, 1), Vector3(0, 0, 1)])
    arrays[Mesh.ARRAY_TANGENT] = PoolRealArray([1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1])
    arrays[Mesh.ARRAY_TEX_UV] = PoolVector2Array([Vector2(uv[0], uv[1]), Vector2(uv[2], uv[1]), Vector2(uv[0], uv[3]), Vector2(uv[2], uv[3])])
    if colors != null:
        arrays[Mesh.ARRAY_COLOR] = PoolColorArray([Color(colors[0][0], colors[0][1], colors[0][2], colors[0][3]),
            Color(colors[1][0], colors[1][1], colors[1][2], colors[1][3]), Color(colors[2][0], colors[2][1], colors[2][2], colors[2][3]),
            Color(colors[3][0], colors[3][1], colors[3][2], colors[3][3])])
    arrays[Mesh.ARRAY_INDEX] = PoolIntArray([0, 1, 3, 0, 3, 2])  # clockwise seen from the camera: Godot's front faces
    var result = ArrayMesh.new()
    result.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays, [], 0)  # uncompressed: the default stores uv as half floats
    return result

func start(job):
    printerr("HEXC-JOB ", done)
    scene = Spatial.new()
    add_child(scene)
    var f = File.new()
    var shader = Shader.new()
    f.open(job["shader"], File.READ)
    shader.code = f.get_as_text()
    f.close()
    var material = ShaderMaterial.new()
    material.shader = shader
    for uniform in job["textures"]:
        material.set_shader_param(uniform, texture(job["textures"][uniform]))
    var quad = MeshInstance.new()
    if job.has("uv"):
        quad.mesh = mesh(job["uv"], job.get("colors"))
    else:
        quad.mesh = QuadMesh.new()
        quad.mesh.size = Vector2(2, 2)
    quad.material_override = material
    scene.add_child(quad)
    var camera = Camera.new()
    camera.projection = Camera.PROJECTION_ORTHOGONAL
    camera.size = 2
    camera.translation = Vector3(0, 0, 1)
    scene.add_child(camera)
    camera.current = true
    if job.has("light"):
        var light = DirectionalLight.new()
        var d = job["light"]  # towards the light, in view space (x right, y up, z towards the camera)
        light.look_at_from_position(Vector3(0, 0, 0), -Vector3(d[0], d[1], d[2]), Vector3(0, 1, 0) if abs(d[1]) < 0.9 else Vector3(1, 0, 0))
        scene.add_child(light)

# A job's frame is read back on its third frame, when the shader is compiled and the textures uploaded. The viewport's
# image is bottom row first (Godot's docs on capturing a viewport: "flip it on the y-axis"): flip_y makes it top row
# first, which the marker at the top-left checks.
func _process(_delta):
    frames += 1
    var job = jobs[done]
    if frames < (3 if job.has("out") else 2):
        return
    if job.has("out"):
        var image = get_viewport().get_texture().get_data()
        image.flip_y()
        image.save_png(job["out"])
    remove_child(scene)
    scene.queue_free()
    frames = 0
    done += 1
    if done == jobs.size():
        get_tree().quit()
    else:
        start(jobs[done])
