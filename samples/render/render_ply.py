"""Renders a coloured PLY written by isoform with Blender (Cycles, CPU).

usage: blender -b --factory-startup --python-exit-code 1 --python render_ply.py -- \
           IN.ply OUT.png [--view X,Y,Z] [--size W,H] [--samples N]

The PLY's per-vertex red green blue alpha become a colour attribute; the
material reads it for the base colour, a little emission (so that the
seed's colours stay readable in shadow) and the alpha, which Cycles blends
as c_new = (1 - t) c_poly + t c_old with alpha = 1 - t. The camera looks
along --view (the direction from the eye into the scene, as `isoform stack
--view`) at the centre of the mesh's bounding box.
"""
import math
import sys

import bpy
import mathutils


def parse(argv):
    args = {"view": (-1.0, -1.0, -1.0), "size": (480, 360), "samples": 32}
    if len(argv) < 2:
        raise SystemExit("usage: ... -- IN.ply OUT.png [--view X,Y,Z] [--size W,H] [--samples N]")
    args["input"], args["output"] = argv[0], argv[1]
    rest = argv[2:]
    for i in range(0, len(rest) - 1, 2):
        key, value = rest[i], rest[i + 1]
        if key == "--view":
            args["view"] = tuple(float(v) for v in value.split(","))
        elif key == "--size":
            args["size"] = tuple(int(v) for v in value.split(","))
        elif key == "--samples":
            args["samples"] = int(value)
        else:
            raise SystemExit(f"unknown option {key}")
    return args


def clear_scene():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)


def import_ply(path):
    bpy.ops.import_mesh.ply(filepath=path)
    obj = bpy.context.selected_objects[0]
    if not obj.data.vertex_colors:
        raise SystemExit(f"{path}: no vertex colours (red green blue alpha) to render")
    return obj


def vertex_colour_material(layer):
    mat = bpy.data.materials.new("isoform vertex colours")
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    bsdf = nodes["Principled BSDF"]
    attr = nodes.new("ShaderNodeAttribute")
    attr.attribute_name = layer
    links.new(attr.outputs["Color"], bsdf.inputs["Base Color"])
    links.new(attr.outputs["Color"], bsdf.inputs["Emission"])
    links.new(attr.outputs["Alpha"], bsdf.inputs["Alpha"])
    bsdf.inputs["Emission Strength"].default_value = 0.35
    bsdf.inputs["Roughness"].default_value = 0.8
    bsdf.inputs["Specular"].default_value = 0.1
    mat.blend_method = "BLEND"
    mat.show_transparent_back = True
    return mat


def bounding_box(obj):
    points = [obj.matrix_world @ v.co for v in obj.data.vertices]
    lo = mathutils.Vector([min(p[a] for p in points) for a in range(3)])
    hi = mathutils.Vector([max(p[a] for p in points) for a in range(3)])
    return lo, hi


def add_camera_and_light(lo, hi, view):
    centre = (lo + hi) / 2
    radius = max((hi - lo).length / 2, 1e-6)
    direction = mathutils.Vector(view).normalized()
    cam_data = bpy.data.cameras.new("camera")
    cam_data.lens = 50
    cam = bpy.data.objects.new("camera", cam_data)
    bpy.context.scene.collection.objects.link(cam)
    # A 50 mm lens on a 36 mm sensor sees about 39.6 degrees: fit the sphere.
    distance = radius / math.sin(math.radians(39.6 / 2)) * 1.05
    cam.location = centre - direction * distance
    # The camera looks down its -Z axis with its Y axis toward world up.
    cam.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
    cam_data.clip_end = distance * 10
    bpy.context.scene.camera = cam
    sun_data = bpy.data.lights.new("sun", "SUN")
    sun_data.energy = 3.0
    sun = bpy.data.objects.new("sun", sun_data)
    sun.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
    bpy.context.scene.collection.objects.link(sun)


def configure_render(args):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = args["samples"]
    scene.cycles.use_denoising = False
    scene.cycles.transparent_max_bounces = 256
    scene.cycles.max_bounces = 4
    scene.render.resolution_x, scene.render.resolution_y = args["size"]
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.compression = 90
    scene.view_settings.view_transform = "Standard"
    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.9, 0.9, 0.9, 1.0)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.6
    scene.world = world
    scene.render.filepath = args["output"]


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    args = parse(argv)
    clear_scene()
    obj = import_ply(args["input"])
    obj.data.materials.append(vertex_colour_material(obj.data.vertex_colors[0].name))
    lo, hi = bounding_box(obj)
    add_camera_and_light(lo, hi, args["view"])
    configure_render(args)
    bpy.ops.render.render(write_still=True)
    print(f"rendered {args['output']}")


main()
