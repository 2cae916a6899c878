"""Renders the surfaces of an `isoform compare` study with Blender (Cycles,
CPU): isophotes and reflection lines, the two classic pictures of surface
fairness (a kink in a stripe is a normal discontinuity, a sharp bend in it a
curvature jump).

usage: blender -b --factory-startup --python-exit-code 1 --python render_study.py -- \
           STUDY_DIR [--size W,H] [--samples N]

For each STUDY_DIR/surface-<name>.ply (the surface's tessellation with its
exact normals) it writes render-<name>-isophotes.png (stripes of constant
n . l for a light l from the camera's upper left) and
render-<name>-reflection.png (stripes of constant height of the reflected
view ray: the reflection of a room of horizontal light bands). Every
surface is seen by the same camera, fitted to the first one's bounding box.
"""
import glob
import math
import os
import sys

import bpy
import mathutils


def parse(argv):
    args = {"size": (480, 360), "samples": 8}
    if not argv:
        raise SystemExit("usage: ... -- STUDY_DIR [--size W,H] [--samples N]")
    args["study"] = argv[0]
    rest = argv[1:]
    for i in range(0, len(rest) - 1, 2):
        if rest[i] == "--size":
            args["size"] = tuple(int(v) for v in rest[i + 1].split(","))
        elif rest[i] == "--samples":
            args["samples"] = int(rest[i + 1])
        else:
            raise SystemExit(f"unknown option {rest[i]}")
    return args


def clear_scene():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)


def import_ply(path):
    bpy.ops.import_mesh.ply(filepath=path)
    obj = bpy.context.selected_objects[0]
    for poly in obj.data.polygons:
        poly.use_smooth = True
    return obj


def emission_material(name):
    """A new material whose surface is one emission node, lit by nothing:
    (material, nodes, links, the emission node)."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    emit = nodes.new("ShaderNodeEmission")
    links.new(emit.outputs[0], out.inputs["Surface"])
    return mat, nodes, links, emit


def normal_dot(nodes, links, light):
    """The output socket of n . light, n the shading normal."""
    geo = nodes.new("ShaderNodeNewGeometry")
    dot = nodes.new("ShaderNodeVectorMath")
    dot.operation = "DOT_PRODUCT"
    dot.inputs[1].default_value = light
    links.new(geo.outputs["Normal"], dot.inputs[0])
    return dot.outputs["Value"]


def stripe_material(name, kind, light):
    """Emission only, black and white stripes of a scalar: n . l for
    isophotes, the z of the reflected view vector for reflection lines."""
    mat, nodes, links, emit = emission_material(name)
    if kind == "isophotes":
        scalar = normal_dot(nodes, links, light)
        bands = 10.0
    else:
        coords = nodes.new("ShaderNodeTexCoord")
        sep = nodes.new("ShaderNodeSeparateXYZ")
        links.new(coords.outputs["Reflection"], sep.inputs[0])
        scalar = sep.outputs["Z"]
        bands = 8.0
    mul = nodes.new("ShaderNodeMath")
    mul.operation = "MULTIPLY"
    mul.inputs[1].default_value = bands
    links.new(scalar, mul.inputs[0])
    frac = nodes.new("ShaderNodeMath")
    frac.operation = "FRACT"
    links.new(mul.outputs[0], frac.inputs[0])
    step = nodes.new("ShaderNodeMath")
    step.operation = "GREATER_THAN"
    step.inputs[1].default_value = 0.5
    links.new(frac.outputs[0], step.inputs[0])
    ramp = nodes.new("ShaderNodeValToRGB")
    ramp.color_ramp.elements[0].color = (0.05, 0.05, 0.08, 1.0)
    ramp.color_ramp.elements[1].color = (0.95, 0.95, 0.9, 1.0)
    links.new(step.outputs[0], ramp.inputs["Fac"])
    links.new(ramp.outputs["Color"], emit.inputs["Color"])
    return mat


def place_camera(obj):
    corners = [obj.matrix_world @ mathutils.Vector(c) for c in obj.bound_box]
    lo = mathutils.Vector([min(c[i] for c in corners) for i in range(3)])
    hi = mathutils.Vector([max(c[i] for c in corners) for i in range(3)])
    centre, size = (lo + hi) / 2, max((hi - lo).length, 1e-6)
    view = mathutils.Vector((-1.0, -0.8, -0.6)).normalized()
    cam_data = bpy.data.cameras.new("camera")
    cam_data.lens = 50
    cam = bpy.data.objects.new("camera", cam_data)
    bpy.context.scene.collection.objects.link(cam)
    cam.location = centre - view * size * 1.6
    cam.rotation_euler = view.to_track_quat("-Z", "Y").to_euler()
    cam_data.clip_end = size * 10
    bpy.context.scene.camera = cam
    up_left = (-view + mathutils.Vector((0, 0, 0.8))).normalized()
    return cam, tuple(up_left)


def render(path, args):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = args["samples"]
    scene.cycles.use_denoising = False  # Debian's Blender has no OpenImageDenoise
    scene.render.resolution_x, scene.render.resolution_y = args["size"]
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.world = bpy.data.worlds.new("world")
    scene.world.color = (0.3, 0.3, 0.32)
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)


def render_folder(study, args):
    """Renders every surface-<name>.ply of the study folder."""
    plys = sorted(glob.glob(os.path.join(study, "surface-*.ply")))
    if not plys:
        raise SystemExit(f"{study}: no surface-*.ply to render")
    camera, light = None, None
    for ply in plys:
        name = os.path.basename(ply)[len("surface-"):-len(".ply")]
        obj = import_ply(ply)
        if camera is None:
            camera, light = place_camera(obj)
        for kind in ("isophotes", "reflection"):
            obj.data.materials.clear()
            obj.data.materials.append(stripe_material(f"{name} {kind}", kind, light))
            render(os.path.join(study, f"render-{name}-{kind}.png"), args)
        bpy.data.objects.remove(obj, do_unlink=True)


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    args = parse(argv)
    clear_scene()
    render_folder(args["study"], args)


if __name__ == "__main__":
    main()
