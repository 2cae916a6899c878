"""Object > isoform > Compare with Subdivision: the side-vertex surface
(Chapter 6) against the Loop limit surface of the same triangles.

The active mesh goes to the library in WORLD space with its normals (as
Smooth Surface takes them). The library samples every surface it measures
(the flat triangles, Loop's limit, the side-vertex surface) at the same
barycentric points; the Loop limit surface comes back as a second object
"<name>_loop" beside the mesh, and the measures are stored on the mesh
object as the custom property "isoform_compare" (JSON), which the sidebar's
Comparison box shows for the active object or its "_loop" partner.
"""
import json

import bpy
import numpy as np

from .jobs import MeshJobOperator, UserError
from .settings import CompareSettings, SmoothSettings

PROPERTY = "isoform_compare"
LOOP_SUFFIX = "_loop"


class OBJECT_OT_isoform_compare(bpy.types.Operator, CompareSettings, SmoothSettings, MeshJobOperator):
    """Measure the side-vertex surface of the active mesh against its Loop limit surface, shown as a second object"""
    bl_idname = "object.isoform_compare"
    bl_label = "Compare with Subdivision"
    bl_options = {'REGISTER', 'UNDO'}

    _SHARED = CompareSettings._SHARED + ("normal_source",)

    def draw(self, context):
        self.draw_compare_settings(self.layout)
        self.layout.prop(self, "normal_source")

    def prepare(self, context):
        from . import mesh_build
        obj = context.active_object
        if len(obj.data.polygons) == 0:
            raise UserError(f"{obj.name}: the mesh has no faces; nothing to compare")
        world, triangles, matrix = mesh_build.world_triangles(obj)
        normals = mesh_build.world_normals(obj, matrix) if self.normal_source == 'MESH' else None
        self._source_name = obj.name
        self._matrix = matrix
        arguments = dict(self.compare_arguments(), input_name=obj.name)
        return lambda progress: _compare(world, triangles, normals, arguments, progress)

    def finish(self, context, result):
        from . import mesh_build
        source = bpy.data.objects.get(self._source_name)
        if source is None:
            raise UserError(f"{self._source_name}: the object went away while it was compared")
        loop = mesh_build.to_object_space(result["tessellations"]["loop"], self._matrix)
        name = self._source_name + LOOP_SUFFIX
        old = bpy.data.objects.get(name)
        if old is not None and old.type == 'MESH':  # a new comparison replaces the old object
            old_mesh = old.data
            bpy.data.objects.remove(old)
            if old_mesh.users == 0:
                bpy.data.meshes.remove(old_mesh)
        mesh_build.add_mesh_object(context, name, loop, source.matrix_world)
        stored = {key: result[key] for key in ("reference", "unit", "metrics")}
        source[PROPERTY] = json.dumps(stored)
        self.report({'INFO'}, summary(self._source_name, stored))


def _compare(points, triangles, normals, arguments, progress):
    """Worker side: plain arrays in, plain values out (no bpy)."""
    from . import native, native_surface
    with native.Mesh.from_arrays_f64(points, triangles) as mesh:
        if normals is not None:
            mesh.set_normals(normals)
        return native_surface.compare(mesh, progress=progress, tessellations=("loop",),
                                      **arguments)


def rows(stored):
    """(surface, normal gap max in degrees, H jump RMS, data point error max,
    deviation RMS or None) per measured surface, for reports and the panel."""
    out = []
    for name, metrics in stored["metrics"].items():
        deviation = metrics["deviation"]
        out.append((name, np.degrees(metrics["normal_gap"]["max"]),
                    metrics["mean_curvature_jump"]["rms"], metrics["data_point_error"]["max"],
                    deviation["rms"] if deviation["count"] else None))
    return out


def summary(name, stored):
    parts = [f"{surface}: normal gap {gap:.3g} deg, H jump {jump:.3g}, data error {error:.3g}"
             for surface, gap, jump, error, _ in rows(stored)]
    return f"{name}: " + "; ".join(parts)


def stored_comparison(obj):
    """The comparison stored on obj, or on the mesh obj is the Loop object of."""
    if obj is None:
        return None, None
    if PROPERTY not in obj and obj.name.endswith(LOOP_SUFFIX):
        obj = bpy.data.objects.get(obj.name[:-len(LOOP_SUFFIX)]) or obj
    if PROPERTY not in obj:
        return None, None
    return obj.name, json.loads(obj[PROPERTY])
