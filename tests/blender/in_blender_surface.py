"""The group "surface" of in_blender.py: Reduce (Chapter 5), Smooth Surface
(Chapter 6) and Compare with Subdivision on mesh objects. One Blender start runs them all.

cases(runner) returns the cases; runner holds in_blender.py's globals (its
expect, scene_counts, expect_operator_error, mesh_arrays, ARGS).
"""
import bpy
import numpy as np

R = None  # in_blender.py, set by cases()


def new_ico_sphere(radius, subdivisions, scale):
    """An icosphere of 20 * 4^(subdivisions - 1) triangles (Blender's count)
    in an object scaled by `scale`, with one material; world radius
    radius * scale."""
    bpy.ops.mesh.primitive_ico_sphere_add(radius=radius, subdivisions=subdivisions)
    obj = bpy.context.view_layer.objects.active
    obj.scale = (scale, scale, scale)
    obj.data.materials.append(bpy.data.materials.new("isoform test material"))
    bpy.context.view_layer.update()
    return obj


def new_mesh_object(name, points, triangles):
    """A mesh object of these triangles, linked and active."""
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(points.tolist(), [], triangles.tolist())
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    return obj


def world_points(obj):
    points = np.empty(len(obj.data.vertices) * 3, dtype=np.float32)
    obj.data.vertices.foreach_get("co", points)
    matrix = np.array(obj.matrix_world, dtype=np.float64)
    return points.reshape(-1, 3).astype(np.float64) @ matrix[:3, :3].T + matrix[:3, 3]


def triangles_of(obj):
    mesh = obj.data
    totals = np.empty(len(mesh.polygons), dtype=np.int32)
    mesh.polygons.foreach_get("loop_total", totals)
    R.expect(np.all(totals == 3), "not all faces are triangles")
    corners = np.empty(len(mesh.loops), dtype=np.int32)
    mesh.loops.foreach_get("vertex_index", corners)
    return corners.reshape(-1, 3)


def expect_closed_manifold(obj):
    """Every edge is shared by exactly two triangles, once in each direction."""
    triangles = triangles_of(obj)
    directed = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    keys = directed[:, 0].astype(np.int64) * len(obj.data.vertices) + directed[:, 1]
    R.expect(len(np.unique(keys)) == len(keys), f"{obj.name}: a directed edge is used twice")
    reverse = directed[:, 1].astype(np.int64) * len(obj.data.vertices) + directed[:, 0]
    R.expect(np.all(np.isin(reverse, keys)), f"{obj.name}: an edge has one triangle only")


# ---------------------------------------------------------------- reduce

def case_reduce_keeps_fraction_closed_on_the_sphere():
    """An icosphere of 5120 triangles, world radius 3, reduced to 20%: the
    same object and material, 1024 triangles as the library makes them, still
    closed with Euler characteristic 2 and its vertices on the sphere."""
    obj = new_ico_sphere(2.0, 5, 1.5)
    name, material = obj.name, obj.data.materials[0]
    before = R.scene_counts()
    result = bpy.ops.object.isoform_reduce(keep_percent=20.0)
    R.expect(result == {'FINISHED'}, f"operator returned {result}")
    R.expect(R.scene_counts() == before, f"scene counts {before} -> {R.scene_counts()}")
    obj = bpy.data.objects[name]
    faces, vertices = len(obj.data.polygons), len(obj.data.vertices)
    R.expect(faces == 1024, f"{faces} triangles, expected 20% of 5120 = 1024")
    R.expect(vertices - len(obj.data.edges) + faces == 2,
             f"Euler characteristic {vertices - len(obj.data.edges) + faces}")
    expect_closed_manifold(obj)
    R.expect(obj.data.materials[0] == material, "the material slot was lost")
    # New points go to the least-squares best place for the original
    # vertices: off the sphere by a fraction of the larger triangles' sagitta.
    radius = np.linalg.norm(world_points(obj), axis=1)
    R.expect(np.all(np.abs(radius - 3.0) < 0.06) and np.sqrt(np.mean((radius - 3.0) ** 2)) < 0.02,
             f"radius {radius.min()}..{radius.max()}")


def case_reduce_keeps_the_name_and_the_faces_materials():
    """An icosphere red below z = 0 and blue above, reduced to 20%: the mesh
    keeps its name, and nearly every new face its half's material."""
    obj = new_ico_sphere(2.0, 4, 1.0)
    mesh_name = obj.data.name
    red, blue = bpy.data.materials.new("isoform red"), bpy.data.materials.new("isoform blue")
    obj.data.materials.clear()
    obj.data.materials.append(red)
    obj.data.materials.append(blue)
    for polygon in obj.data.polygons:
        polygon.material_index = 1 if polygon.center.z > 0 else 0
    R.expect(bpy.ops.object.isoform_reduce(keep_percent=20.0) == {'FINISHED'}, "operator failed")
    R.expect(obj.data.name == mesh_name, f"the mesh {mesh_name!r} came back as {obj.data.name!r}")
    index = np.array([p.material_index for p in obj.data.polygons])
    z = np.array([p.center.z for p in obj.data.polygons])
    away = np.abs(z) > 0.3  # clear of the seam
    right = np.mean(index[away] == (z[away] > 0))
    R.expect(right > 0.98 and set(index) == {0, 1}, f"{right:.3f} of the faces keep their half's material")


def case_reduce_matches_library():
    """The operator's mesh equals the library's reduction of the same world
    triangles, mapped back into the object's space."""
    from isoform_blender import mesh_build, native, native_surface
    obj = new_ico_sphere(1.0, 3, 2.0)
    world, triangles, matrix = mesh_build.world_triangles(obj)
    with native.Mesh.from_arrays_f64(world, triangles) as mesh:
        native_surface.reduce(mesh, keep_fraction=0.5)
        expected = mesh_build.to_object_space(mesh.arrays(), matrix)
    R.expect(bpy.ops.object.isoform_reduce(keep_percent=50.0) == {'FINISHED'}, "operator failed")
    R.expect(np.array_equal(triangles_of(obj), expected.triangles), "triangles differ")
    points = np.empty(len(obj.data.vertices) * 3, dtype=np.float32)
    obj.data.vertices.foreach_get("co", points)
    R.expect(np.allclose(points.reshape(-1, 3), expected.points, atol=1e-6), "points differ")


def case_reduce_errors_leave_the_mesh():
    """A mesh without faces, and a non-manifold one (three triangles on an
    edge): Blender error reports, the mesh as it was."""
    mesh = bpy.data.meshes.new("isoform points only")
    mesh.vertices.add(3)
    obj = bpy.data.objects.new("isoform points only", mesh)
    bpy.context.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    R.expect_operator_error(bpy.ops.object.isoform_reduce, ["no faces"])
    fin = bpy.data.meshes.new("isoform fin")
    fin.from_pydata([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1)], [],
                    [(0, 1, 2), (1, 0, 3), (0, 1, 4)])
    obj = bpy.data.objects.new("isoform fin", fin)
    bpy.context.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    R.expect_operator_error(bpy.ops.object.isoform_reduce, ["edge"])
    R.expect(len(obj.data.polygons) == 3, "the non-manifold mesh was changed")


def case_reduce_no_overlap():
    """No Overlap on a thin torus shell reduced to 2%: the operator gives the
    library's guarded reduction, whose sheets do not cross (the library
    reduces it again); without it they do."""
    from isoform_blender import mesh_build, native, native_surface
    from thin_shell import thin_shell
    points, shell_triangles = thin_shell()
    results = {}
    for guard in (False, True):
        obj = new_mesh_object("isoform shell", points, shell_triangles)
        result = bpy.ops.object.isoform_reduce(keep_percent=2.0, prevent_overlap=guard)
        R.expect(result == {'FINISHED'}, f"operator returned {result}")
        expect_closed_manifold(obj)
        world, triangles, _ = mesh_build.world_triangles(obj)
        with native.Mesh.from_arrays_f64(world, triangles) as again:
            try:
                native_surface.reduce(again, keep_fraction=0.5)
                results[guard] = "reduced again"
            except native.IsoformError as error:
                results[guard] = str(error)
    R.expect("overlaps itself" in results[False], f"unguarded: {results[False]}")
    R.expect(results[True] == "reduced again", f"No Overlap: {results[True]}")


def case_reduce_height_field():
    """Height Field on the paraboloid over [-1, 1]^2 reduced to 10%: the
    operator gives the library's graph reduction (the square stays covered
    once); the same object turned upside down is refused, the mesh as it was."""
    from height_field import paraboloid_grid, projected_areas
    points, triangles = paraboloid_grid(41)
    obj = new_mesh_object("isoform terrain", points, triangles)
    result = bpy.ops.object.isoform_reduce(keep_percent=10.0, height_field=True)
    R.expect(result == {'FINISHED'}, f"operator returned {result}")
    areas = projected_areas(world_points(obj), triangles_of(obj))
    R.expect(len(areas) <= 320 and areas.min() > 0 and abs(areas.sum() - 4) < 1e-5,
             f"{len(areas)} triangles, smallest area {areas.min()}, sum {areas.sum()}")
    obj.rotation_euler = (np.pi, 0.0, 0.0)  # seen from above, every face now turns clockwise
    bpy.context.view_layer.update()
    count = len(obj.data.polygons)
    R.expect_operator_error(bpy.ops.object.isoform_reduce, ["not a graph"], keep_percent=50.0,
                            height_field=True)
    R.expect(len(obj.data.polygons) == count, "the refused mesh was changed")


# ---------------------------------------------------------------- smooth surface

def case_smooth_surface_beside_the_mesh():
    """An icosphere of 80 triangles (world radius 3), level 2: a new closed
    object of 80 * 16 triangles beside it, far closer to the sphere than the
    flat triangles, the source kept."""
    obj = new_ico_sphere(2.0, 2, 1.5)
    name = obj.name
    result = bpy.ops.object.isoform_smooth(level=2)
    R.expect(result == {'FINISHED'}, f"operator returned {result}")
    smooth = bpy.context.view_layer.objects.active
    R.expect(smooth.name == f"{name}_smooth", f"new object {smooth.name}")
    R.expect(len(bpy.data.objects[name].data.polygons) == 80, "the source mesh changed")
    R.expect(len(smooth.data.polygons) == 80 * 16, f"{len(smooth.data.polygons)} triangles")
    expect_closed_manifold(smooth)
    base = world_points(bpy.data.objects[name])[triangles_of(bpy.data.objects[name])]
    flat_gap = 3.0 - np.linalg.norm(base.mean(axis=1), axis=1).min()
    gap = np.abs(np.linalg.norm(world_points(smooth), axis=1) - 3.0).max()
    R.expect(flat_gap > 0.15 and gap < flat_gap / 4,
             f"smooth surface leaves the sphere by up to {gap}; the flat triangles by {flat_gap}")
    R.expect(smooth.data.materials[0] == obj.data.materials[0], "the material was not copied")


def case_smooth_surface_follows_level_and_blend():
    """Level 0 gives the base triangles' count; printed and squared blends
    give different surfaces through the same vertices."""
    obj = new_ico_sphere(1.0, 2, 1.0)
    bpy.ops.object.select_all(action='DESELECT')
    bpy.context.view_layer.objects.active = obj
    R.expect(bpy.ops.object.isoform_smooth(level=0) == {'FINISHED'}, "level 0 failed")
    R.expect(len(bpy.context.view_layer.objects.active.data.polygons) == 80, "level 0 count")
    surfaces = []
    for blend in ("printed", "squared"):
        bpy.context.view_layer.objects.active = obj
        R.expect(bpy.ops.object.isoform_smooth(level=3, blend=blend) == {'FINISHED'}, blend)
        surfaces.append(world_points(bpy.context.view_layer.objects.active))
    R.expect(surfaces[0].shape == surfaces[1].shape, "blends give different counts")
    R.expect(np.abs(surfaces[0] - surfaces[1]).max() > 1e-5, "the blend option has no effect")


# ---------------------------------------------------------------- compare

def case_compare_adds_the_loop_object_and_stores_metrics():
    """An icosphere of 320 triangles: a "<name>_loop" object of 320 * 9
    triangles beside it; the measures stored on the mesh name the three
    surfaces, the side-vertex surface through the data points, Loop not;
    running it again replaces the Loop object."""
    import json
    obj = new_ico_sphere(1.0, 3, 1.0)
    name = obj.name
    result = bpy.ops.object.isoform_compare(compare_level=3, reference='sphere')
    R.expect(result == {'FINISHED'}, f"operator returned {result}")
    loop = bpy.data.objects.get(f"{name}_loop")
    R.expect(loop is not None and len(loop.data.polygons) == 320 * 9,
             f"loop object {loop and len(loop.data.polygons)}")
    expect_closed_manifold(loop)
    stored = json.loads(bpy.data.objects[name]["isoform_compare"])
    metrics = stored["metrics"]
    R.expect(set(metrics) == {"linear", "loop", "side-vertex"}, f"surfaces {sorted(metrics)}")
    R.expect(metrics["side-vertex"]["data_point_error"]["max"] < 1e-5 <
             metrics["loop"]["data_point_error"]["max"], "data point errors")
    objects = len(bpy.data.objects)
    bpy.context.view_layer.objects.active = bpy.data.objects[name]
    R.expect(bpy.ops.object.isoform_compare(compare_level=2) == {'FINISHED'}, "second run")
    R.expect(len(bpy.data.objects) == objects, "a second comparison added another object")
    R.expect(len(bpy.data.objects[f"{name}_loop"].data.polygons) == 320 * 4, "not replaced")


def cases(runner):
    global R
    R = runner
    return [case_reduce_keeps_fraction_closed_on_the_sphere, case_reduce_keeps_the_name_and_the_faces_materials,
            case_reduce_matches_library,
            case_reduce_errors_leave_the_mesh, case_reduce_no_overlap, case_reduce_height_field,
            case_smooth_surface_beside_the_mesh,
            case_smooth_surface_follows_level_and_blend,
            case_compare_adds_the_loop_object_and_stores_metrics]
