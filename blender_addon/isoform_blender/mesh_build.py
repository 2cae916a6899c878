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
    mesh.vertices.add(len(points))
    mesh.vertices.foreach_set("co", points.ravel())
    _add_triangles(mesh, triangles)
    mesh.polygons.foreach_set("use_smooth", np.ones(len(triangles), dtype=bool))
    mesh.update(calc_edges=True)
    _set_normals(mesh, arrays.normals)
    _set_part(mesh, arrays.parts)


def _add_triangles(mesh, triangles):
    m = len(triangles)
    mesh.loops.add(3 * m)
    mesh.loops.foreach_set("vertex_index", triangles.ravel())
    mesh.polygons.add(m)
    mesh.polygons.foreach_set("loop_start", np.arange(0, 3 * m, 3, dtype=np.int32))
    if _loop_total_is_writable():
        mesh.polygons.foreach_set("loop_total", np.full(m, 3, dtype=np.int32))


def fill_coloured_mesh(mesh, arrays, layer="isoform_color"):
    """Adds a native_visualize.ColouredArrays to an empty mesh: its loose
    edges (curves, the domain box) first, then its triangles, and its RGBA
    colours as the active POINT colour attribute `layer`."""
    points = np.ascontiguousarray(arrays.points, dtype=np.float32)
    edges = np.ascontiguousarray(arrays.edges, dtype=np.int32)
    mesh.vertices.add(len(points))
    mesh.vertices.foreach_set("co", points.ravel())
    if len(edges):
        mesh.edges.add(len(edges))
        mesh.edges.foreach_set("vertices", edges.ravel())
    _add_triangles(mesh, np.ascontiguousarray(arrays.triangles, dtype=np.int32))
    mesh.update(calc_edges=True)  # keeps the loose edges added above
    if arrays.colors is not None:
        set_point_colours(mesh, layer, arrays.colors)


def srgb_to_linear(values):
    """The sRGB transfer function inverted (colour attributes hold linear values)."""
    return np.where(values <= 0.04045, values / 12.92, ((values + 0.055) / 1.055) ** 2.4)


def set_point_colours(mesh, name, rgba):
    """rgba: (n, 4) uint8 sRGB colours with linear alpha, as the library
    makes them. Replaces an attribute of that name; becomes the active and
    rendered colour attribute (Solid > Attribute shows it)."""
    if name in mesh.attributes:
        mesh.attributes.remove(mesh.attributes[name])
    linear = np.asarray(rgba, dtype=np.float32) / 255.0
    linear[:, :3] = srgb_to_linear(linear[:, :3])
    attribute = mesh.attributes.new(name=name, type='BYTE_COLOR', domain='POINT')
    attribute.data.foreach_set("color", np.ascontiguousarray(linear, dtype=np.float32).ravel())
    # Colour attributes and these two properties exist from Blender 3.2.
    mesh.attributes.active_color = attribute
    mesh.attributes.render_color_index = mesh.attributes.active_color_index
    return attribute


def set_point_values(mesh, name, values):
    """A FLOAT (n,) or FLOAT_VECTOR (n, 3) POINT attribute, replacing one of that name."""
    if name in mesh.attributes:
        mesh.attributes.remove(mesh.attributes[name])
    values = np.ascontiguousarray(values, dtype=np.float32)
    kind, field = ('FLOAT', "value") if values.ndim == 1 else ('FLOAT_VECTOR', "vector")
    attribute = mesh.attributes.new(name=name, type=kind, domain='POINT')
    attribute.data.foreach_set(field, values.ravel())
    return attribute


def _set_normals(mesh, normals):
    # NOTE: up to Blender 4.0 custom normals are used only with auto smooth
    # on; 4.1 removed the property and always uses them.
    if hasattr(mesh, "use_auto_smooth"):
        mesh.use_auto_smooth = True
    mesh.normals_split_custom_set_from_vertices(np.ascontiguousarray(normals, dtype=np.float32))


def _set_part(mesh, parts):
    attribute = mesh.attributes.new(name="part", type='INT', domain='FACE')
    attribute.data.foreach_set("value", np.ascontiguousarray(parts, dtype=np.int32))


def add_mesh_object(context, name, arrays, matrix_world=None, fill=fill_mesh):
    """A new object named name in the active collection, selected and active.
    Nothing is left behind if building the mesh fails."""
    mesh = new_mesh(name, arrays, fill)
    obj = bpy.data.objects.new(name, mesh)
    if matrix_world is not None:
        obj.matrix_world = matrix_world
    context.collection.objects.link(obj)
    for other in list(context.view_layer.objects.selected):
        other.select_set(False)
    obj.select_set(True)
    context.view_layer.objects.active = obj
    return obj


def new_mesh(name, arrays, fill=fill_mesh):
    """A new mesh datablock filled by fill(mesh, arrays), removed again if that fails."""
    mesh = bpy.data.meshes.new(name)
    try:
        fill(mesh, arrays)
    except Exception:
        bpy.data.meshes.remove(mesh)
        raise
    return mesh


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


def world_triangles(obj):
    """(points (n, 3) float64 in world space, triangles (m, 3) int32, the
    object's 4x4 matrix as float64) of a mesh object: what the library sees
    of it, in the units the user sees."""
    points, triangles = triangle_arrays(obj.data)
    matrix = np.array(obj.matrix_world, dtype=np.float64)
    world = points.astype(np.float64) @ matrix[:3, :3].T + matrix[:3, 3]
    return world, triangles, matrix


def to_object_space(arrays, matrix):
    """arrays (native.MeshArrays in world space) with points and normals
    mapped into the object space of a 4x4 world matrix: points by its
    inverse, normals by its transpose (the inverse transpose of the inverse)."""
    linear = matrix[:3, :3]
    points = (np.asarray(arrays.points, dtype=np.float64) - matrix[:3, 3]) @ np.linalg.inv(linear).T
    normals = np.asarray(arrays.normals, dtype=np.float64) @ linear
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = np.where(length > 0, normals / np.maximum(length, 1e-300), 0.0)
    arrays.points = points.astype(np.float32)
    arrays.normals = normals.astype(np.float32)
    return arrays


def vertex_normals(mesh):
    """(n, 3) float32 unit normals per vertex as Blender shades the mesh: its
    custom normals when it has them (a contour import sets them per vertex),
    else its vertex normals; +z for a vertex that has neither."""
    normals = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("normal", normals)
    normals = normals.reshape(-1, 3).astype(np.float64)
    if mesh.has_custom_normals and len(mesh.loops):
        corners = np.empty(len(mesh.loops) * 3, dtype=np.float32)
        # NOTE: up to Blender 4.0 corner normals need calc_normals_split();
        # 4.1 replaced loops' normal by mesh.corner_normals.
        if hasattr(mesh, "calc_normals_split"):
            mesh.calc_normals_split()
            mesh.loops.foreach_get("normal", corners)
        else:
            mesh.corner_normals.foreach_get("vector", corners)
        vertex = np.empty(len(mesh.loops), dtype=np.int32)
        mesh.loops.foreach_get("vertex_index", vertex)
        summed = np.zeros_like(normals)
        np.add.at(summed, vertex, corners.reshape(-1, 3))
        has_corners = np.linalg.norm(summed, axis=1) > 0
        normals[has_corners] = summed[has_corners]
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    unit = np.where(length > 0, normals / np.maximum(length, 1e-300), [0.0, 0.0, 1.0])
    return unit.astype(np.float32)


def replace_geometry(obj, arrays):
    """Gives obj a new mesh datablock built from arrays (object space), with
    the old one's name (unless another object still uses the old one, which
    keeps it), materials and faces' materials (carry_material_indices); the
    old one goes when nothing else uses it. Nothing changes if building
    fails."""
    old = obj.data
    name = old.name
    mesh = new_mesh(name, arrays)
    for material in old.materials:
        mesh.materials.append(material)
    carry_material_indices(old, mesh)
    obj.data = mesh
    if old.users == 0:
        bpy.data.meshes.remove(old)
        mesh.name = name
    return mesh


def face_centres(mesh):
    centres = np.empty(3 * len(mesh.polygons), dtype=np.float32)
    mesh.polygons.foreach_get("center", centres)
    return centres.reshape(-1, 3)


def carry_material_indices(old, mesh):
    """Each face of mesh takes the material of the face of old whose centre
    is nearest its own (both in object space): the reduction keeps no record
    of which faces replaced which, and its faces lie on the old surface."""
    count = len(old.polygons)
    if len(old.materials) < 2 or count == 0 or len(mesh.polygons) == 0:
        return
    index = np.empty(count, dtype=np.int32)
    old.polygons.foreach_get("material_index", index)
    if not index.any():
        return
    from mathutils import kdtree
    tree = kdtree.KDTree(count)
    for i, centre in enumerate(face_centres(old)):
        tree.insert(centre, i)
    tree.balance()
    nearest = np.array([tree.find(c)[1] for c in face_centres(mesh)], dtype=np.int64)
    mesh.polygons.foreach_set("material_index", index[nearest])


def world_normals(obj, matrix):
    """The mesh's vertex normals (vertex_normals) in world space, by the
    inverse transpose of the 4x4 world matrix, as float64."""
    return vertex_normals(obj.data).astype(np.float64) @ np.linalg.inv(matrix[:3, :3])

