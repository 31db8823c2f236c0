# tools/bench/scenes/cornell_diffuse.json rebuilt for Blender's Cycles, rendered headless:
#   blender -b --factory-startup --python tools/bench/cycles/cornell_diffuse.py -- \
#       OUT.exr SAMPLES THREADS SEED
# rt's coordinates are y-up, Blender's z-up: rt (x, y, z) is Blender (x, -z, y). The settings
# match rt's path tracer: no denoising, no adaptive sampling, no clamping, a box pixel filter one
# pixel wide, 8 bounces, linear output (OpenEXR, the Standard view), a black world. The light is
# a rectangle that emits from its lower face only, radiance (12, 11, 9) as in the rt scene.
# Prints "cycles: render N.NNN s" (the render alone, without Blender's start-up).
import sys
import time

import bpy

out, samples, threads, seed = sys.argv[sys.argv.index("--") + 1:][:4]


def rt_point(x, y, z):
    return (x, -z, y)


def material(name, colour, emission=None):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes = m.node_tree.nodes
    links = m.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    if emission is None:
        diffuse = nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = (*colour, 1)
        links.new(diffuse.outputs["BSDF"], output.inputs["Surface"])
        return m
    # Emission on the front face only: black diffuse behind it, as rt's one-sided rectangle.
    emit = nodes.new("ShaderNodeEmission")
    emit.inputs["Color"].default_value = (*[c / emission for c in colour], 1)
    emit.inputs["Strength"].default_value = emission
    black = nodes.new("ShaderNodeBsdfDiffuse")
    black.inputs["Color"].default_value = (0, 0, 0, 1)
    side = nodes.new("ShaderNodeNewGeometry")
    mix = nodes.new("ShaderNodeMixShader")
    links.new(side.outputs["Backfacing"], mix.inputs["Fac"])
    links.new(emit.outputs["Emission"], mix.inputs[1])
    links.new(black.outputs["BSDF"], mix.inputs[2])
    links.new(mix.outputs["Shader"], output.inputs["Surface"])
    return m


def box(lo, hi, m):
    centre = rt_point(*[(a + b) / 2 for a, b in zip(lo, hi)])
    size = [b - a for a, b in zip(lo, hi)]
    bpy.ops.mesh.primitive_cube_add(size=1, location=centre)
    cube = bpy.context.object
    cube.scale = (size[0], size[2], size[1])
    cube.data.materials.append(m)


def rectangle_light(corner, edge_u, edge_v, radiance):
    points = [corner,
              [c + u for c, u in zip(corner, edge_u)],
              [c + u + v for c, u, v in zip(corner, edge_u, edge_v)],
              [c + v for c, v in zip(corner, edge_v)]]
    mesh = bpy.data.meshes.new("light")
    # Winding corner, +u, +u+v, +v: the normal is cross(edge_u, edge_v), rt's emitting side.
    mesh.from_pydata([rt_point(*p) for p in points], [], [(0, 1, 2, 3)])
    light = bpy.data.objects.new("light", mesh)
    bpy.context.scene.collection.objects.link(light)
    light.data.materials.append(material("light", radiance, emission=max(radiance)))


scene = bpy.context.scene
for o in list(scene.objects):
    bpy.data.objects.remove(o)
white = material("white", (0.75, 0.75, 0.75))
red = material("red", (0.7, 0.1, 0.08))
green = material("green", (0.12, 0.6, 0.15))
box((-1.1, -0.1, -1.1), (1.1, 0, 1.1), white)
box((-1.1, 2, -1.1), (1.1, 2.1, 1.1), white)
box((-1.1, 0, -1.1), (1.1, 2, -1), white)
box((-1.1, 0, -1), (-1, 2, 1.1), red)
box((1, 0, -1), (1.1, 2, 1.1), green)
box((-0.7, 0, -0.65), (-0.1, 1.2, -0.05), white)
box((0.1, 0, 0.05), (0.7, 0.6, 0.65), white)
rectangle_light((-0.35, 1.99, -0.35), (0.7, 0, 0), (0, 0, 0.7), (12, 11, 9))

camera = bpy.data.cameras.new("camera")
camera.sensor_fit = "VERTICAL"
camera.angle_y = 45 * 3.141592653589793 / 180
eye = bpy.data.objects.new("camera", camera)
eye.location = rt_point(0, 1, 3.4)
eye.rotation_euler = (3.141592653589793 / 2, 0, 0)  # looking along rt's -z
scene.collection.objects.link(eye)
scene.camera = eye

world = bpy.data.worlds.new("black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (0, 0, 0, 1)
scene.world = world

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = int(samples)
scene.cycles.seed = int(seed)
scene.cycles.use_denoising = False
scene.cycles.use_adaptive_sampling = False
scene.cycles.sample_clamp_direct = 0
scene.cycles.sample_clamp_indirect = 0
scene.cycles.pixel_filter_type = "BOX"
scene.cycles.filter_width = 1.0
scene.cycles.max_bounces = 8
scene.cycles.diffuse_bounces = 8
scene.render.threads_mode = "FIXED"
scene.render.threads = int(threads)
scene.render.resolution_x = 200
scene.render.resolution_y = 200
scene.render.resolution_percentage = 100
scene.view_settings.view_transform = "Standard"
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.filepath = out

start = time.perf_counter()
bpy.ops.render.render(write_still=True)
print("cycles: render %.3f s" % (time.perf_counter() - start))
