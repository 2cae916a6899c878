"""Blender meshes to and from isoform arrays (native.MeshArrays).

Everything goes through foreach_set / foreach_get on contiguous float32 and
int32 arrays: no from_pydata, no per-element Python loops.
"""
import bpy
import numpy as np


def _loop_total_is_writable():
    # NOTE: Blender 3.4 and 3.5 store loop_total per polygon and need it set;
    # from 3.6 it is read-only, derived from the next polygon's loop_start.
    return not bpy.types.MeshPolygon.bl_rna.properties["loop_total"].is_readonly


def fill_mesh(mesh, arrays):
    """Adds arrays' triangles to an empty mesh, with custom normals and the
    face attribute `part` (0 = the largest connected part)."""
    points = np.ascontiguousarray(arrays.points, dtype=np.float32)
    triangles = np.ascontiguousarray(arrays.triangles, dtype=np.int32)
    n, m = len(points), len(triangles)
    mesh.vertices.add(n)
    mesh.vertices.foreach_set("co", points.ravel())
    mesh.loops.add(3 * m)
    mesh.loops.foreach_set("vertex_index", triangles.ravel())
    mesh.polygons.add(m)
    mesh.polygons.foreach_set("loop_start", np.arange(0, 3 * m, 3, dtype=np.int32))
    if _loop_total_is_writable():
        mesh.polygons.foreach_set("loop_total", np.full(m, 3, dtype=np.int32))
    mesh.polygons.foreach_set("use_smooth", np.ones(m, dtype=bool))
    mesh.update(calc_edges=True)
    _set_normals(mesh, arrays.normals)
    _set_part(mesh, arrays.parts)


def _set_normals(mesh, normals):
    # NOTE: up to Blender 4.0 custom normals are used only with auto smooth
    # on; 4.1 removed the property and always uses them.
    if hasattr(mesh, "use_auto_smooth"):
        mesh.use_auto_smooth = True
    mesh.normals_split_custom_set_from_vertices(np.ascontiguousarray(normals, dtype=np.float32))


def _set_part(mesh, parts):
    attribute = mesh.attributes.new(name="part", type='INT', domain='FACE')
    attribute.data.foreach_set("value", np.ascontiguousarray(parts, dtype=np.int32))


def add_mesh_object(context, name, arrays, matrix_world=None):
    """A new object named name in the active collection, selected and active.
    Nothing is left behind if building the mesh fails."""
    mesh = bpy.data.meshes.new(name)
    try:
        fill_mesh(mesh, arrays)
    except Exception:
        bpy.data.meshes.remove(mesh)
        raise
    obj = bpy.data.objects.new(name, mesh)
    if matrix_world is not None:
        obj.matrix_world = matrix_world
    context.collection.objects.link(obj)
    for other in list(context.view_layer.objects.selected):
        other.select_set(False)
    obj.select_set(True)
    context.view_layer.objects.active = obj
    return obj


def triangle_arrays(mesh):
    """(points (n, 3) float32, triangles (m, 3) int32) of a Blender mesh, its
    faces triangulated as Blender draws them: the input of
    native.Mesh.from_arrays for operators that work on an existing mesh."""
    mesh.calc_loop_triangles()
    points = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", points)
    triangles = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int32)
    mesh.loop_triangles.foreach_get("vertices", triangles)
    return points.reshape(-1, 3), triangles.reshape(-1, 3)
