"""Object > isoform > Smooth Surface: the side-vertex surface (Chapter 6).

The tangent-plane-continuous surface through the active mesh's vertices,
with its normals there, tessellated at a level as a new object beside it
("<name>_smooth", same transform). The data go to the library in WORLD space
(normals by the inverse transpose of the object's matrix) and the result
comes back into object space, its vertex normals the surface's exact ones.
"""
import bpy

from .jobs import MeshJobOperator, UserError
from .settings import SmoothSettings


class OBJECT_OT_isoform_smooth(bpy.types.Operator, SmoothSettings, MeshJobOperator):
    """The side-vertex surface through the active mesh's vertices and normals (Hamann 1991, Chapter 6) as a new object"""
    bl_idname = "object.isoform_smooth"
    bl_label = "Smooth Surface"
    bl_options = {'REGISTER', 'UNDO'}

    def draw(self, context):
        self.draw_smooth_settings(self.layout)

    def prepare(self, context):
        from . import mesh_build
        obj = context.active_object
        if len(obj.data.polygons) == 0:
            raise UserError(f"{obj.name}: the mesh has no faces; it carries no surface")
        world, triangles, matrix = mesh_build.world_triangles(obj)
        normals = mesh_build.world_normals(obj, matrix) if self.normal_source == 'MESH' else None
        self._source_name = obj.name
        self._object_name = f"{obj.name}_smooth"
        self._matrix = matrix
        level, arguments = self.level, self.patch_arguments()
        return lambda progress: _smooth(world, triangles, normals, level, arguments, progress)

    def finish(self, context, result):
        from . import mesh_build
        arrays, stats = result
        source = bpy.data.objects.get(self._source_name)
        obj = mesh_build.add_mesh_object(context, self._object_name,
                                         mesh_build.to_object_space(arrays, self._matrix),
                                         source.matrix_world if source else None)
        if source is not None:
            for material in source.data.materials:
                obj.data.materials.append(material)
        self.report({'INFO'}, f"{self._object_name}: {len(arrays.triangles)} triangles at level "
                              f"{self.level}; {stats.nonconvex_edges} of {stats.edges} edges "
                              f"non-convex")


def _smooth(points, triangles, normals, level, arguments, progress):
    """Worker side: plain arrays in, plain arrays out (no bpy)."""
    from . import native, native_surface
    with native.Mesh.from_arrays_f64(points, triangles) as mesh:
        if normals is not None:
            mesh.set_normals(normals)
        with native_surface.Patch.create(mesh, **arguments) as patch:
            stats = patch.stats()
            with patch.tessellate(level, progress=progress) as smooth:
                return smooth.arrays(), stats
