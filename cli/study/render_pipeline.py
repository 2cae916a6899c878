"""The pictures of `isoform pipeline`, made in one Blender run (Cycles, CPU):
the contour coloured by its mean curvature, the reduced mesh with its
triangles drawn, the side-vertex surface, and the comparison study's
isophotes and reflection lines (render_study.py).

usage: blender -b --factory-startup --python-exit-code 1 --python render_pipeline.py -- \
           FOLDER NAME [--size W,H] [--samples N]

Reads FOLDER/NAME-curvature.ply (vertex colours by mean curvature),
NAME-reduced.ply, NAME-smooth.ply and NAME-study/; writes
FOLDER/NAME-curvature.png, NAME-reduced.png, NAME-smooth.png and the
study's render-*.png. The three meshes are seen by one camera fitted to the
contour, lit by a light from the camera's upper left.
"""
import os
import sys

import bpy
import mathutils

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_study as study  # noqa: E402


def parse(argv):
    if len(argv) < 2:
        raise SystemExit("usage: ... -- FOLDER NAME [--size W,H] [--samples N]")
    args = study.parse([argv[0]] + argv[2:])
    args["folder"], args["name"] = argv[0], argv[1]
    return args


def shaded_material(name, light, vertex_colours, wire):
    """Emission of a base colour (the mesh's vertex colours, or light grey)
    darkened where the surface turns from the light; with wire, the
    triangles' edges drawn dark over it."""
    mat, nodes, links, emit = study.emission_material(name)
    shade = nodes.new("ShaderNodeMapRange")  # n.l in [-0.2, 1] -> [0.15, 1]
    shade.inputs["From Min"].default_value = -0.2
    shade.inputs["To Min"].default_value = 0.15
    links.new(study.normal_dot(nodes, links, light), shade.inputs["Value"])
    mix = nodes.new("ShaderNodeMixRGB")
    mix.blend_type = "MULTIPLY"
    mix.inputs["Fac"].default_value = 1.0
    if vertex_colours:
        colours = nodes.new("ShaderNodeAttribute")
        colours.attribute_name = vertex_colours
        links.new(colours.outputs["Color"], mix.inputs["Color1"])
    else:
        mix.inputs["Color1"].default_value = (0.8, 0.78, 0.72, 1.0)
    links.new(shade.outputs["Result"], mix.inputs["Color2"])
    colour = mix.outputs["Color"]
    if wire:
        edges = nodes.new("ShaderNodeWireframe")
        edges.use_pixel_size = True
        edges.inputs["Size"].default_value = 1.0
        over = nodes.new("ShaderNodeMixRGB")
        links.new(edges.outputs["Fac"], over.inputs["Fac"])
        links.new(colour, over.inputs["Color1"])
        over.inputs["Color2"].default_value = (0.08, 0.08, 0.1, 1.0)
        colour = over.outputs["Color"]
    links.new(colour, emit.inputs["Color"])
    return mat


def key_light():
    """From the camera's upper left: the direction study.place_camera looks
    along is (-1, -0.8, -0.6)."""
    view = mathutils.Vector((-1.0, -0.8, -0.6)).normalized()
    left = mathutils.Vector((0.0, 0.0, 1.0)).cross(view).normalized()
    return tuple((-0.6 * view + 0.6 * mathutils.Vector((0.0, 0.0, 1.0)) + 0.5 * left).normalized())


def colour_attribute(obj):
    """The name under which Blender's PLY importer put the vertex colours."""
    names = [a.name for a in obj.data.color_attributes] if hasattr(obj.data, "color_attributes") else []
    return names[0] if names else None


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    args = parse(argv)
    folder, name = args["folder"], args["name"]
    study.clear_scene()
    # Colours as written (Blender's default view transform would wash the
    # colour map out).
    bpy.context.scene.view_settings.view_transform = "Standard"
    light, placed = key_light(), False
    for stem, wire, smooth in (("curvature", False, True), ("reduced", True, False), ("smooth", False, True)):
        obj = study.import_ply(os.path.join(folder, f"{name}-{stem}.ply"))
        for poly in obj.data.polygons:
            poly.use_smooth = smooth
        if not placed:
            study.place_camera(obj)
            placed = True
        colours = colour_attribute(obj) if stem == "curvature" else None
        obj.data.materials.append(shaded_material(stem, light, colours, wire))
        study.render(os.path.join(folder, f"{name}-{stem}.png"), args)
        bpy.data.objects.remove(obj, do_unlink=True)
    study.clear_scene()
    study.render_folder(os.path.join(folder, f"{name}-study"), args)


if __name__ == "__main__":
    main()
