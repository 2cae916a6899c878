"""Object > isoform > Slices, Boxes, Stack: Chapter 2's volume visualisations
of the active volume object (its .vdb as the Contour operator resolves it).

The library works in the grids' world coordinates, which are the volume
object's space: every object made here gets the volume's matrix_world, so
it sits where the volume is. Colours are the library's, as the POINT colour
attribute `isoform_color`, which the materials read (Attribute node).
"""
import os

import bpy
from bpy.props import EnumProperty, FloatProperty, FloatVectorProperty, IntProperty
from bpy.props import IntVectorProperty, StringProperty

from .jobs import JobOperator

COLOUR_LAYER = "isoform_color"
_MAPS = (
    ("viridis", "Viridis", "Perceptually uniform, dark blue to yellow"),
    ("diverging", "Diverging", "Blue, white at 0, red; range symmetric about 0"),
    ("green-white", "Green-White", "Low green to high white (Hamann 1991, Figures 2.2-2.4)"),
)


def _map_property(default):
    return EnumProperty(name="Colours", items=_MAPS, default=default,
                        description="Colour map of the linear colour-index map (Section 2.2)")


class _VolumeVisual(JobOperator):
    """Mixin: an operator on the active volume object whose work is one
    library call on its file, producing coloured meshes."""
    grid: StringProperty(name="Grid", default="",
                         description="Name of the grid to show; empty: the first scalar grid")

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == 'VOLUME'

    def prepare(self, context):
        from . import volume_source
        obj = context.active_object
        self._path, self._temporary = volume_source.volume_file(context, obj)
        self._volume_name = obj.name
        self._matrix = obj.matrix_world.copy()
        path, grid, calls = self._path, self.grid, self.calls(context)
        return lambda progress: _run_calls(path, grid, calls)

    def cleanup(self):
        if getattr(self, "_temporary", False) and os.path.exists(self._path):
            os.remove(self._path)
        self._temporary = False

    def place(self, context, name, arrays, material):
        """The object called name, made or re-filled with arrays, at the volume."""
        from . import mesh_build
        mesh = mesh_build.new_mesh(name, arrays, mesh_build.fill_coloured_mesh)
        mesh.materials.append(material)
        obj = bpy.data.objects.get(name)
        if obj is not None and obj.type == 'MESH':
            old, obj.data = obj.data, mesh  # re-slicing: the same object, new geometry
            if old.users == 0:
                bpy.data.meshes.remove(old)
        else:
            obj = bpy.data.objects.new(name, mesh)
            context.collection.objects.link(obj)
        obj.matrix_world = self._matrix
        return obj


def _run_calls(path, grid, calls):
    """Worker side: opens the file once and runs each call(volume, grid)."""
    from . import native, native_visualize
    with native.Volume.open(path) as volume:
        index = volume.find_grid(grid)
        return [native_visualize.coloured_arrays(call(volume, index)) for call in calls]


def vertex_colour_material(name, blend=False):
    """A material whose base colour (and alpha, when blend) is `isoform_color`."""
    material = bpy.data.materials.get(name) or bpy.data.materials.new(name)
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    bsdf = _principled(nodes, links)
    attribute = nodes.get("isoform colour") or nodes.new("ShaderNodeAttribute")
    attribute.name = "isoform colour"
    attribute.attribute_name = COLOUR_LAYER
    links.new(attribute.outputs["Color"], bsdf.inputs["Base Color"])
    if blend:
        links.new(attribute.outputs["Alpha"], bsdf.inputs["Alpha"])
        # NOTE: blend_method is EEVEE's (3.4 to 4.1; 4.2 keeps it as a legacy
        # setting). Faces are drawn in their order, which the library sorted
        # back to front, when show_transparent_back is on.
        material.blend_method = 'BLEND'
        material.show_transparent_back = True
    return material


def _principled(nodes, links):
    """The material's Principled BSDF, made and linked to the output if absent."""
    for node in nodes:
        if node.type == 'BSDF_PRINCIPLED':
            return node
    bsdf = nodes.new("ShaderNodeBsdfPrincipled")
    output = next((n for n in nodes if n.type == 'OUTPUT_MATERIAL'), None)
    if output is None:
        output = nodes.new("ShaderNodeOutputMaterial")
    links.new(bsdf.outputs["BSDF"], output.inputs["Surface"])
    return bsdf


class OBJECT_OT_isoform_slices(bpy.types.Operator, _VolumeVisual):
    """Three orthogonal slice planes through the active volume (Hamann 1991, Section 2.3)"""
    bl_idname = "object.isoform_slices"
    bl_label = "Slices"
    bl_options = {'REGISTER', 'UNDO'}

    x: FloatProperty(name="x", default=0.5, min=0.0, max=1.0,
                     description="Position of the plane x = c1 across the domain, 0..1")
    y: FloatProperty(name="y", default=0.5, min=0.0, max=1.0,
                     description="Position of the plane y = c2 across the domain, 0..1")
    z: FloatProperty(name="z", default=0.5, min=0.0, max=1.0,
                     description="Position of the plane z = c3 across the domain, 0..1")
    resolution: IntProperty(name="Resolution", default=128, min=2, max=4096,
                            description="Samples along the longer side of each slice")
    colour_map: _map_property("viridis")

    def calls(self, context):
        from . import native_visualize
        keywords = {"position": (self.x, self.y, self.z), "resolution": self.resolution,
                    "colour_map": self.colour_map}
        return [lambda volume, grid, axis=axis: native_visualize.slice_mesh(
            volume, grid, axis, "plane", **keywords) for axis in range(3)]

    def finish(self, context, results):
        material = vertex_colour_material("isoform slice")
        for axis, arrays in enumerate(results):
            self.place(context, f"{self._volume_name}_slice_{'xyz'[axis]}", arrays, material)


class OBJECT_OT_isoform_boxes(bpy.types.Operator, _VolumeVisual):
    """The domain-subdivision boxes of the active volume (Hamann 1991, Section 2.2)"""
    bl_idname = "object.isoform_boxes"
    bl_label = "Boxes"
    bl_options = {'REGISTER', 'UNDO'}

    q: IntVectorProperty(name="q", size=3, default=(5, 5, 5), min=1, max=64,
                         description="Subvolumes per axis")
    gap: FloatProperty(name="Gap", default=1.0, min=0.0, max=10.0,
                       description="Gap between subvolumes over their edge (alpha)")
    face_cells: IntVectorProperty(name="Face Cells", size=2, default=(1, 1), min=1, max=64,
                                  description="Each face is a k x l grid of Gouraud cells")
    colour_map: _map_property("green-white")

    def calls(self, context):
        from . import native_visualize
        keywords = {"q": tuple(self.q), "gap": self.gap, "face_cells": tuple(self.face_cells),
                    "colour_map": self.colour_map}
        return [lambda volume, grid: native_visualize.boxes(volume, grid, **keywords)]

    def finish(self, context, results):
        material = vertex_colour_material("isoform boxes")
        self.place(context, f"{self._volume_name}_boxes", results[0], material)


class OBJECT_OT_isoform_stack(bpy.types.Operator, _VolumeVisual):
    """The transparency stack of the active volume, sorted for a view (Hamann 1991, Section 2.2)"""
    bl_idname = "object.isoform_stack"
    bl_label = "Stack"
    bl_options = {'REGISTER', 'UNDO'}

    n: IntVectorProperty(name="n", size=3, default=(8, 8, 8), min=1, max=256,
                         description="Cells of the evaluation grid per axis")
    transparency: FloatProperty(name="Transparency", default=0.5, min=0.0, max=1.0,
                                description="t of Section 2.2; alpha = 1 - t")
    # SKIP_SAVE: a remembered last value would count as set and hide the
    # current view's direction from invoke().
    view: FloatVectorProperty(name="View", size=3, default=(-1.0, -1.0, -1.0),
                              options={'SKIP_SAVE'},
                              description="Viewing direction, from the eye into the scene, in "
                                          "world space (invoked from a 3D view: that view's)")
    colour_map: _map_property("viridis")

    def invoke(self, context, event):
        region = context.region_data
        if region is not None and not self.properties.is_property_set("view"):
            from mathutils import Vector
            self.view = region.view_rotation @ Vector((0.0, 0.0, -1.0))
        return super().invoke(context, event)

    def calls(self, context):
        from . import native_visualize
        # The library sorts in the grids' space, the volume's object space.
        local = context.active_object.matrix_world.to_3x3().inverted_safe() @ self._view_vector()
        keywords = {"n": tuple(self.n), "transparency": self.transparency,
                    "view": tuple(local), "colour_map": self.colour_map}
        return [lambda volume, grid: native_visualize.stack(volume, grid, **keywords)]

    def _view_vector(self):
        from mathutils import Vector
        return Vector(self.view)

    def finish(self, context, results):
        material = vertex_colour_material("isoform stack", blend=True)
        self.place(context, f"{self._volume_name}_stack", results[0], material)
