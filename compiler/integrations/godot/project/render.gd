# Renders each job of job.json in turn: its shader (a hexc package's, or the test's value view of it) on a quad that
# fills the window, its textures bound as the job says, under the job's light if any; saves each frame as PNG, then
# quits.
extends Spatial

var frames = 0
var jobs = []
var scene = null

func _ready():
    var f = File.new()
    f.open("res://job.json", File.READ)
    jobs = parse_json(f.get_as_text())["jobs"]
    f.close()
    start(jobs[0])

func start(job):
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
        var t = job["textures"][uniform]
        var image = Image.new()
        if image.load(t["path"]) != OK:
            print("HEXC-ERROR cannot load ", t["path"])
        var flags = Texture.FLAG_MIPMAPS | Texture.FLAG_REPEAT | Texture.FLAG_FILTER
        if t["srgb"]:
            flags |= Texture.FLAG_CONVERT_TO_LINEAR
        var texture = ImageTexture.new()
        texture.create_from_image(image, flags)
        material.set_shader_param(uniform, texture)
    var quad = MeshInstance.new()
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

# A job's frame is read back on its third frame, when the shader is compiled and the textures uploaded.
func _process(_delta):
    frames += 1
    if frames < 3:
        return
    var image = get_viewport().get_texture().get_data()
    image.flip_y()
    image.save_png(jobs[0]["out"])
    jobs.pop_front()
    remove_child(scene)
    scene.queue_free()
    frames = 0
    if jobs.empty():
        get_tree().quit()
    else:
        start(jobs[0])
