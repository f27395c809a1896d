"""Renders one of this project's scene files with Blender's Cycles (issue 42's peer), headless.

    blender -b --factory-startup -noaudio -P tests/Bench/cycles/cycles_render.py -- SCENE.json OUT.pfm SPP WIDTH THREADS

SCENE.json: a scene as `ray-tracing-cpu --scene ID --export-scene SCENE.json` writes it (docs/SCENES.md). What
Cycles is given is that scene: its quads and triangle meshes (instances' 3x4 matrices applied), Lambertian
materials and one-sided diffuse lights of solid colour, a constant background and the pinhole camera. Anything
else (spheres, media, metal, glass, textures) is refused with one line, so that a comparison never runs on a
scene Cycles was given differently.

The render matches this project's estimator's assumptions where Cycles lets it: a box pixel filter one pixel
wide, no adaptive sampling, no denoising, no clamping, no light threshold, the scene's depth as every bounce
limit, the Standard view transform; OUT.pfm holds Cycles' linear radiance (float RGB, rows from the bottom, as
this project's PFMs), OUT.pfm.exr the EXR Cycles wrote. Prints one JSON line:
{"render_seconds": ..., "spp": ..., "width": ..., "height": ..., "threads": ...}, render_seconds being
bpy.ops.render.render's time (Cycles' scene sync and BVH build included: about a millisecond for these scenes).
Debian: apt-get install blender (3.4.1 in bookworm).
"""
import array
import json
import math
import sys
import time

import bpy
from mathutils import Matrix, Vector


def fail(message):
    print(f"error: {message}", file=sys.stderr)
    sys.exit(2)


def solid(textures, index, what):
    texture = textures[index]
    if texture.get("type") != "solid":
        fail(f"{what}: only solid colours are given to Cycles (texture {index} is {texture.get('type')})")
    return texture["color"]


def material(scene, index, cache):
    if index in cache:
        return cache[index]
    desc = scene["materials"][index]
    m = bpy.data.materials.new(f"material {index}")
    m.use_nodes = True
    nodes, links = m.node_tree.nodes, m.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    if desc["type"] == "lambertian":
        r, g, b = solid(scene["textures"], desc["albedo_texture"], f"material {index}")
        bsdf = nodes.new("ShaderNodeBsdfDiffuse")
        bsdf.inputs["Color"].default_value = (r, g, b, 1.0)
        bsdf.inputs["Roughness"].default_value = 0.0  # Lambert, not Oren-Nayar
        links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    elif desc["type"] == "diffuse_light":
        if not scene["render"].get("unidirectional_light", True):
            fail("two-sided emitters are not given to Cycles")
        r, g, b = solid(scene["textures"], desc["radiance_texture"], f"material {index}")
        peak = max(r, g, b, 1e-30)
        emission = nodes.new("ShaderNodeEmission")  # radiance = colour x strength (a surface seen directly)
        emission.inputs["Color"].default_value = (r / peak, g / peak, b / peak, 1.0)
        emission.inputs["Strength"].default_value = peak
        # One-sided, as this project's emitters: the back face emits nothing and reflects nothing.
        black = nodes.new("ShaderNodeEmission")
        black.inputs["Strength"].default_value = 0.0
        geometry = nodes.new("ShaderNodeNewGeometry")
        mix = nodes.new("ShaderNodeMixShader")
        links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
        links.new(emission.outputs["Emission"], mix.inputs[1])
        links.new(black.outputs["Emission"], mix.inputs[2])
        links.new(mix.outputs["Shader"], out.inputs["Surface"])
    else:
        fail(f"material {index} is {desc['type']}: only lambertian and diffuse_light are given to Cycles")
    cache[index] = m
    return m


def shape_faces(shape):
    """The shape as vertices and faces, wound so that Blender's normal is the project's front (u x v)."""
    if shape["type"] == "quad":
        q, u, v = (Vector(shape[k]) for k in ("q", "u", "v"))
        return [q, q + u, q + u + v, q + v], [(0, 1, 2, 3)]
    fail(f"a {shape['type']} shape: only quads are given to Cycles")


def add_instances(scene, materials):
    for n, instance in enumerate(scene["instances"]):
        group = scene["groups"][instance["group"]]
        matrix = Matrix.Identity(4)
        for step in instance.get("transform", []):
            if "matrix" not in step:
                fail(f"instance {n}: only matrix transforms are given to Cycles")
            rows = step["matrix"]
            matrix = Matrix((rows[0], rows[1], rows[2], (0.0, 0.0, 0.0, 1.0))) @ matrix
        for k, shape in enumerate(group["shapes"]):
            vertices, faces = shape_faces(shape)
            mesh = bpy.data.meshes.new(f"{group['name']} {k}")
            mesh.from_pydata([matrix @ p for p in vertices], [], faces)
            mesh.materials.append(material(scene, shape["material"], materials))
            bpy.context.collection.objects.link(bpy.data.objects.new(mesh.name, mesh))
    if scene.get("meshes"):
        fail("triangle meshes are not given to Cycles yet")


def add_camera(scene, width, aspect):
    desc = scene["camera"]
    if desc.get("defocus_angle", 0.0) > 0.0:
        fail("a thin-lens camera is not given to Cycles")
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    data.angle = math.radians(desc["vfov"])
    data.clip_start = 1e-3  # Blender's defaults (0.1 to 1000) would cut a scene of this project's scale
    data.clip_end = 1e9
    camera = bpy.data.objects.new("camera", data)
    eye, target, up = (Vector(desc[k]) for k in ("look_from", "look_at", "up"))
    forward = (target - eye).normalized()
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    # Blender's camera looks along its -Z with +Y up.
    camera.matrix_world = Matrix((
        (right.x, true_up.x, -forward.x, eye.x),
        (right.y, true_up.y, -forward.y, eye.y),
        (right.z, true_up.z, -forward.z, eye.z),
        (0.0, 0.0, 0.0, 1.0),
    ))
    bpy.context.collection.objects.link(camera)
    render = bpy.context.scene.render
    render.resolution_x = width
    render.resolution_y = max(1, int(width / aspect))
    render.resolution_percentage = 100
    bpy.context.scene.camera = camera


def configure(scene, spp, threads, out):
    background = scene["background"]
    if background.get("type") != "constant":
        fail("only a constant background is given to Cycles")
    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (*background["color"], 1.0)
    bpy.context.scene.world = world
    s = bpy.context.scene
    s.render.engine = "CYCLES"
    c = s.cycles
    c.device = "CPU"
    c.samples = spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.filter_width = 1.0
    c.pixel_filter_type = "BOX"
    depth = scene["render"].get("depth", 50)
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = depth
    c.volume_bounces = c.transparent_max_bounces = depth
    c.caustics_reflective = c.caustics_refractive = True
    c.seed = 0
    s.render.threads_mode = "FIXED"
    s.render.threads = threads
    s.render.use_persistent_data = False
    s.view_settings.view_transform = "Standard"
    s.view_settings.look = "None"
    s.view_settings.exposure = 0.0
    s.view_settings.gamma = 1.0
    s.render.image_settings.file_format = "OPEN_EXR"
    s.render.image_settings.color_depth = "32"
    s.render.image_settings.exr_codec = "ZIP"
    s.render.filepath = out


def write_pfm(path, image, width, height):
    """The image's RGB as a little-endian float PFM (Blender's pixels run from the bottom row, as PFM's do)."""
    pixels = image.pixels[:]
    rgb = array.array("f", (pixels[i] for i in range(len(pixels)) if i % 4 != 3))
    if sys.byteorder != "little":
        rgb.byteswap()
    with open(path, "wb") as f:
        f.write(f"PF\n{width} {height}\n-1.0\n".encode())
        f.write(rgb.tobytes())


def main(argv):
    if len(argv) != 5:
        fail("usage: blender -b -P cycles_render.py -- SCENE.json OUT.pfm SPP WIDTH THREADS")
    path, out, spp, width, threads = argv[0], argv[1], int(argv[2]), int(argv[3]), int(argv[4])
    with open(path) as f:
        scene = json.load(f)
    if scene.get("origin") and any(scene["origin"]):
        fail("a scene with an origin is not given to Cycles")
    bpy.ops.wm.read_factory_settings(use_empty=True)
    add_instances(scene, {})
    add_camera(scene, width, scene["render"].get("aspect", 1.0))
    configure(scene, spp, threads, out + ".exr")
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    seconds = time.perf_counter() - start
    r = bpy.context.scene.render
    write_pfm(out, bpy.data.images.load(out + ".exr"), r.resolution_x, r.resolution_y)
    print(json.dumps({"render_seconds": seconds, "spp": spp, "width": r.resolution_x, "height": r.resolution_y,
                      "threads": threads}))


main(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])
