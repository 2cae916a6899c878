"""Object > isoform > Reduce: curvature-driven triangle removal (Chapter 5).

The active mesh goes to the library as Blender triangulates it, in WORLD
space (the tolerance is a world distance and curvature weights see the
surface as it is rendered), and comes back into the object's own space as a
new mesh datablock with the old one's name and materials, each new face
taking the material of the old face nearest it: the object keeps its
transform, modifiers and material slots. Undo restores the old mesh.
"""
import bpy

from .jobs import MeshJobOperator, UserError
from .settings import ReduceSettings

_STOP_REASONS = ("target reached", "nothing more removable", "tolerance reached",
                 "graph RMS tolerance reached")


class OBJECT_OT_isoform_reduce(bpy.types.Operator, ReduceSettings, MeshJobOperator):
    """Remove triangles where the active mesh is flat, keep them where it bends (Hamann 1991, Chapter 5)"""
    bl_idname = "object.isoform_reduce"
    bl_label = "Reduce"
    bl_options = {'REGISTER', 'UNDO'}

    def draw(self, context):
        self.draw_reduce_settings(self.layout)

    def prepare(self, context):
        from . import mesh_build
        obj = context.active_object
        if len(obj.data.polygons) == 0:
            raise UserError(f"{obj.name}: the mesh has no faces; nothing to reduce")
        world, triangles, matrix = mesh_build.world_triangles(obj)
        self._object_name = obj.name
        self._matrix = matrix
        arguments = self.reduce_arguments()
        return lambda progress: _reduce(world, triangles, arguments, progress)

    def finish(self, context, result):
        from . import mesh_build
        arrays, stats = result
        obj = bpy.data.objects.get(self._object_name)
        if obj is None or obj.type != 'MESH':
            raise UserError(f"{self._object_name}: the object went away while it was reduced")
        mesh_build.replace_geometry(obj, mesh_build.to_object_space(arrays, self._matrix))
        self.report({'INFO'}, summary(self._object_name, stats, self.height_field))


def _reduce(points, triangles, arguments, progress):
    """Worker side: plain arrays in, plain arrays out (no bpy)."""
    from . import native, native_surface
    with native.Mesh.from_arrays_f64(points, triangles) as mesh:
        stats = native_surface.reduce(mesh, progress=progress, **arguments)
        return mesh.arrays(), stats


def summary(name, stats, height_field=False):
    reason = (_STOP_REASONS[stats.stop_reason] if 0 <= stats.stop_reason < len(_STOP_REASONS)
              else "?")
    text = (f"{name}: {stats.triangles_before} -> {stats.triangles_after} triangles, "
            f"{stats.vertices_before} -> {stats.vertices_after} vertices in {stats.passes} "
            f"passes; {reason}")
    if height_field:
        text += f"; RMS height error {stats.graph_rms:.4g}"
    return text
