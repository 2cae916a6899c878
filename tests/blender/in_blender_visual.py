"""The group "visual" of in_blender.py: Curvature on a mesh; Slices, Boxes
and Stack on a volume object. One Blender start runs them all.

cases(runner) returns the cases; runner holds in_blender.py's globals (its
expect, scene_counts, new_volume_object, expect_operator_error,
library_message, ARGS).
"""
import bpy
import numpy as np

R = None  # in_blender.py, set by cases()


def point_values(mesh, name, width=1):
    attribute = mesh.attributes[name]
    R.expect(attribute.domain == 'POINT', f"{name} is on {attribute.domain}")
    field = "value" if width == 1 else "vector"
    values = np.empty(len(mesh.vertices) * width, dtype=np.float32)
    attribute.data.foreach_get(field, values)
    return values if width == 1 else values.reshape(-1, 3)


def points_of(obj):
    points = np.empty(len(obj.data.vertices) * 3, dtype=np.float32)
    obj.data.vertices.foreach_get("co", points)
    return points.reshape(-1, 3)


def colours_as_bytes(mesh, name):
    """The colour attribute read back as the library's sRGB bytes."""
    attribute = mesh.attributes[name]
    linear = np.empty(len(mesh.vertices) * 4, dtype=np.float32)
    attribute.data.foreach_get("color", linear)
    linear = linear.reshape(-1, 4)
    rgb = np.where(linear[:, :3] <= 0.0031308, linear[:, :3] * 12.92,
                   1.055 * np.power(np.maximum(linear[:, :3], 0), 1 / 2.4) - 0.055)
    return np.rint(np.column_stack([rgb, linear[:, 3]]) * 255).astype(np.int32)


# ---------------------------------------------------------------- curvature

def case_curvature_uv_sphere():
    """A UV sphere of radius 2 in an object scaled by 1.5: world radius 3, so
    mean = k1 = k2 = 1/3 (positive: the surface bends away from its outward
    normal) at nearly all vertices; the colour attribute is active."""
    bpy.ops.mesh.primitive_uv_sphere_add(radius=2.0, segments=64, ring_count=32)
    obj = bpy.context.view_layer.objects.active
    obj.scale = (1.5, 1.5, 1.5)
    bpy.context.view_layer.update()
    result = bpy.ops.object.isoform_curvature(curvature_method='quartic', color_by='gauss')
    R.expect(result == {'FINISHED'}, f"operator returned {result}")
    mesh = obj.data
    for name in ("k1", "k2", "mean", "gauss", "absolute"):
        R.expect(mesh.attributes[name].data_type == 'FLOAT', f"{name} type")
    mean = point_values(mesh, "mean")
    near = np.mean(np.abs(mean * 3.0 - 1.0) < 0.03)
    R.expect(near > 0.95, f"{near:.1%} of the vertices have mean within 3% of 1/3; "
                          f"median {np.median(mean)}")
    gauss = np.median(point_values(mesh, "gauss"))
    R.expect(abs(gauss * 9.0 - 1.0) < 0.03, f"median gauss {gauss}, expected 1/9")
    k1, k2 = point_values(mesh, "k1"), point_values(mesh, "k2")
    R.expect(np.all(k1 >= k2), "k1 < k2")
    d1 = point_values(mesh, "d1", 3)
    R.expect(mesh.attributes["d1"].data_type == 'FLOAT_VECTOR' and
             np.allclose(np.linalg.norm(d1, axis=1), 1.0, atol=1e-4), "d1 not unit vectors")
    normals = points_of(obj) / 2.0  # object space: the direction lies in the tangent plane
    R.expect(np.percentile(np.abs(np.einsum("ij,ij->i", d1, normals)), 95) < 0.05,
             "d1 not tangent to the sphere")
    colour = mesh.attributes.active_color
    R.expect(colour is not None and colour.name == "curvature_color" and
             colour.domain == 'POINT' and colour.data_type == 'BYTE_COLOR',
             f"active colour {colour and colour.name}")
    R.expect(mesh.attributes.render_color_index == mesh.attributes.active_color_index,
             "the curvature colour is not the rendered one")
    R.expect(len(np.unique(colours_as_bytes(mesh, "curvature_color")[:, :3], axis=0)) > 1,
             "all vertices have one colour")


def case_curvature_matches_library_and_reruns():
    """The attributes equal the library's curvature of the same triangles
    (world positions, double precision); running again replaces them."""
    from isoform_blender import mesh_build, native
    bpy.ops.mesh.primitive_ico_sphere_add(radius=1.0, subdivisions=4)
    obj = bpy.context.view_layer.objects.active
    for _ in range(2):
        result = bpy.ops.object.isoform_curvature(curvature_method='cubic', color_by='mean')
        R.expect(result == {'FINISHED'}, f"operator returned {result}")
    points, triangles = mesh_build.triangle_arrays(obj.data)
    with native.Mesh.from_arrays_f64(points.astype(np.float64), triangles) as mesh:
        mesh.curvature(method="cubic", color_by="mean")
        expected, colours = mesh.curvature_values("k1"), mesh.colors()
    R.expect(np.array_equal(point_values(obj.data, "k1"), expected), "k1 differs from the library")
    R.expect(np.array_equal(colours_as_bytes(obj.data, "curvature_color"), colours),
             "colours differ from the library's")
    R.expect(sum(a.name == "k1" for a in obj.data.attributes) == 1, "k1 twice after a re-run")


def case_curvature_no_faces():
    mesh = bpy.data.meshes.new("points only")
    mesh.vertices.add(3)
    obj = bpy.data.objects.new("points only", mesh)
    bpy.context.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    names = sorted(a.name for a in mesh.attributes)
    R.expect_operator_error(bpy.ops.object.isoform_curvature, ["points only", "no faces"])
    R.expect(sorted(a.name for a in mesh.attributes) == names, "attributes changed")


# ---------------------------------------------------------------- volume

def smoke_volume(name):
    import os
    obj = R.new_volume_object(name, os.path.join(R.ARGS.data, "smoke.vdb"))
    obj.location = (1.0, 2.0, 3.0)
    bpy.context.view_layer.update()
    return obj


def plane_coordinate(obj, axis):
    """The coordinate `axis` of the vertices the slice's faces use (the
    loose domain-box edges have their own vertices)."""
    corners = np.empty(len(obj.data.loops), dtype=np.int32)
    obj.data.loops.foreach_get("vertex_index", corners)
    return points_of(obj)[np.unique(corners), axis]


def case_slices_three_objects_and_reslice():
    from isoform_blender import native, native_visualize
    volume = smoke_volume("smoke_slices")
    before = R.scene_counts()
    result = bpy.ops.object.isoform_slices(x=0.3, y=0.5, z=0.5, resolution=16)
    R.expect(result == {'FINISHED'}, f"operator returned {result}")
    R.expect(R.scene_counts()[0] == before[0] + 3, f"{before} -> {R.scene_counts()}")
    names = [f"smoke_slices_slice_{a}" for a in "xyz"]
    objects = [bpy.data.objects[n] for n in names]
    # Blender keeps float properties in single precision: x is float32(0.3).
    with native.Volume.open(volume.data.filepath) as handle:
        expected = native_visualize.coloured_arrays(native_visualize.slice_mesh(
            handle, "", 0, position=(float(np.float32(0.3)), 0.5, 0.5), resolution=16))
    got = points_of(objects[0])
    R.expect(got.shape == expected.points.shape and np.array_equal(got, expected.points),
             f"x slice: {got.shape} points, the library's {expected.points.shape}; "
             f"{got[:2].tolist()} vs {expected.points[:2].tolist()}")
    R.expect(np.array_equal(colours_as_bytes(objects[0].data, "isoform_color"), expected.colors),
             "x slice colours differ from the library's")
    R.expect(all(o.matrix_world == volume.matrix_world for o in objects), "not at the volume")
    R.expect(all(o.active_material and o.active_material.name.startswith("isoform slice")
                 for o in objects), "slice material")
    x_before = plane_coordinate(objects[0], 0)
    y_before = points_of(objects[1])
    R.expect(np.ptp(x_before) < 1e-4, "the x slice is not a plane x = c")
    bpy.context.view_layer.objects.active = volume
    result = bpy.ops.object.isoform_slices(x=0.7, y=0.5, z=0.5, resolution=16)
    R.expect(result == {'FINISHED'}, f"re-slice returned {result}")
    R.expect(R.scene_counts()[0] == before[0] + 3, "re-slicing added objects")
    x_after = plane_coordinate(bpy.data.objects[names[0]], 0)
    low, high = expected.points[:, 0].min(), expected.points[:, 0].max()
    R.expect(np.allclose(x_before, low + 0.3 * (high - low), atol=1e-3) and
             np.allclose(x_after, low + 0.7 * (high - low), atol=1e-3),
             f"x plane {x_before[0]} -> {x_after[0]} in {low}..{high}")
    R.expect(np.array_equal(points_of(bpy.data.objects[names[1]]), y_before),
             "the y slice moved with x")


def case_boxes_counts():
    """q = 2,3,1, face cells 2,1: 6 q k l quads, 2 triangles each."""
    smoke_volume("smoke_boxes")
    result = bpy.ops.object.isoform_boxes(q=(2, 3, 1), gap=1.0, face_cells=(2, 1))
    R.expect(result == {'FINISHED'}, f"operator returned {result}")
    obj = bpy.data.objects["smoke_boxes_boxes"]
    boxes = 6
    R.expect(len(obj.data.polygons) == 2 * 6 * boxes * 2 and
             len(obj.data.vertices) == 6 * boxes * 3 * 2,
             f"{len(obj.data.vertices)} vertices {len(obj.data.polygons)} faces")
    R.expect(obj.data.attributes.active_color.name == "isoform_color", "no active colour")


def case_stack_counts_and_alpha_material():
    """n = 2,3,4: 3 n_x n_y n_z + n_x n_y + n_x n_z + n_y n_z rectangles;
    alpha 1 - t; a BLEND material reading the colour's alpha."""
    smoke_volume("smoke_stack")
    result = bpy.ops.object.isoform_stack(n=(2, 3, 4), transparency=0.75, view=(-1, -0.5, -2))
    R.expect(result == {'FINISHED'}, f"operator returned {result}")
    obj = bpy.data.objects["smoke_stack_stack"]
    rectangles = 3 * 24 + 6 + 8 + 12
    R.expect(len(obj.data.polygons) == 2 * rectangles and
             len(obj.data.vertices) == 4 * rectangles,
             f"{len(obj.data.vertices)} vertices {len(obj.data.polygons)} faces")
    alpha = colours_as_bytes(obj.data, "isoform_color")[:, 3]
    R.expect(np.all(alpha == 64), f"alpha bytes {set(alpha.tolist())}")
    material = obj.active_material
    R.expect(material.blend_method == 'BLEND', f"blend {material.blend_method}")
    links = [(l.from_socket.name, l.to_socket.name) for l in material.node_tree.links]
    R.expect(("Alpha", "Alpha") in links, f"alpha not linked: {links}")


def case_volume_operator_errors():
    from isoform_blender import native, native_visualize
    with native.Volume.open(R.ARGS.vector_vdb) as volume:
        message = R.library_message(lambda: native_visualize.slice_mesh(volume, ""))
    for operator in (bpy.ops.object.isoform_slices, bpy.ops.object.isoform_boxes,
                     bpy.ops.object.isoform_stack):
        R.new_volume_object("vector_visual", R.ARGS.vector_vdb)
        R.expect_operator_error(operator, [message, "velocity"])
        R.new_volume_object("missing_visual", R.ARGS.scratch + "/absent.vdb")
        R.expect_operator_error(operator, ["missing_visual", "no grids"])


def cases(runner):
    global R
    R = runner
    return [case_curvature_uv_sphere, case_curvature_matches_library_and_reruns,
            case_curvature_no_faces, case_slices_three_objects_and_reslice, case_boxes_counts,
            case_stack_counts_and_alpha_material, case_volume_operator_errors]
