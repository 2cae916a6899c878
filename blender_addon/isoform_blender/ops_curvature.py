"""Object > isoform > Curvature: principal curvatures of a mesh as attributes.

The mesh goes to the library as Blender triangulates it (loop triangles),
with its vertex positions in WORLD space (the object's matrix applied, in
double precision): the values are the curvature of the surface as it is
seen and rendered, in 1/world unit (gauss in 1/world unit^2), also for a
scaled object. The directions d1, d2 are mapped back into object space
(tangent vectors, by the inverse of the matrix) and normalised, so that they
lie along the mesh as stored. Sign: positive where the surface bends away
from its outward normal (the winding of the faces): a UV sphere of radius r
gets k1 = k2 = mean = 1/r.

Written as POINT attributes: FLOAT k1 k2 mean gauss absolute, FLOAT_VECTOR
d1 d2, INT curvature_flags, and the BYTE_COLOR `curvature_color` of the
chosen quantity, made the active colour (Solid > Attribute shows it).
"""
import bpy
import numpy as np

from .jobs import MeshJobOperator, UserError
from .settings import CurvatureSettings

QUANTITIES = ("k1", "k2", "mean", "gauss", "absolute")
DIRECTIONS = ("d1", "d2")
COLOUR_LAYER = "curvature_color"
_FLAG_NAMES = ("boundary", "widened", "lower_order", "nonmanifold", "isolated", "failed",
               "normal_repaired")


class OBJECT_OT_isoform_curvature(bpy.types.Operator, CurvatureSettings, MeshJobOperator):
    """Principal curvatures of the active mesh (Hamann 1991, Section 4.2) as point attributes"""
    bl_idname = "object.isoform_curvature"
    bl_label = "Curvature"
    bl_options = {'REGISTER', 'UNDO'}

    def draw(self, context):
        self.draw_curvature_settings(self.layout)

    def prepare(self, context):
        from . import mesh_build
        obj = context.active_object
        if len(obj.data.polygons) == 0:
            raise UserError(f"{obj.name}: the mesh has no faces; curvature needs a surface")
        world, triangles, matrix = mesh_build.world_triangles(obj)
        self._object_name = obj.name
        arguments = self.curvature_arguments()
        to_object = np.linalg.inv(matrix[:3, :3])
        return lambda progress: _curvature(world, triangles, arguments, to_object, progress)

    def finish(self, context, result):
        from . import mesh_build
        obj = bpy.data.objects.get(self._object_name)
        if obj is None or obj.type != 'MESH' or len(obj.data.vertices) != len(result["mean"]):
            raise UserError(f"{self._object_name}: the mesh changed while its curvature was "
                            f"computed; nothing was written")
        mesh = obj.data
        for name in QUANTITIES + DIRECTIONS:
            mesh_build.set_point_values(mesh, name, result[name])
        flags = mesh.attributes.get("curvature_flags")
        if flags is not None:
            mesh.attributes.remove(flags)
        flags = mesh.attributes.new(name="curvature_flags", type='INT', domain='POINT')
        flags.data.foreach_set("value", result["flags"].astype(np.int32))
        mesh_build.set_point_colours(mesh, COLOUR_LAYER, result["colors"])
        mesh.update()
        self.report({'INFO'}, summary(self._object_name, result["stats"]))


def _curvature(points, triangles, arguments, to_object, progress):
    """Worker side: plain arrays in, plain arrays out (no bpy)."""
    from . import native
    with native.Mesh.from_arrays_f64(points, triangles) as mesh:
        stats = mesh.curvature(progress=progress, **arguments)
        result = {name: mesh.curvature_values(name) for name in QUANTITIES}
        for name in DIRECTIONS:
            local = mesh.curvature_values(name).astype(np.float64) @ to_object.T
            length = np.linalg.norm(local, axis=1, keepdims=True)
            result[name] = np.where(length > 0, local / np.maximum(length, 1e-300), 0.0)
        result["flags"] = mesh.curvature_flags()
        result["colors"] = mesh.colors()
    result["stats"] = stats
    return result


def summary(name, stats):
    """One line for the INFO report: the colour range and the fallbacks."""
    fallbacks = [f"{getattr(stats, flag)} {flag.replace('_', ' ')}" for flag in _FLAG_NAMES
                 if getattr(stats, flag)]
    quantity = QUANTITIES[stats.color_by] if 0 <= stats.color_by < len(QUANTITIES) else "?"
    return (f"{name}: curvature of {stats.vertices} vertices; colours show {quantity} "
            f"{stats.color_min:.4g} .. {stats.color_max:.4g}; fallbacks: "
            + (", ".join(fallbacks) if fallbacks else "none"))
