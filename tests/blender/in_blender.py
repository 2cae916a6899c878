"""The add-on inside headless Blender; run by run_blender.py, which passes the
expected figures from the isoform command.

blender -b --factory-startup --python-exit-code 1 --python in_blender.py -- GROUP ...

Groups: import (operators give the CLI's counts), errors (the library's
message reaches the user, the scene is left as it was), render (Cycles sees
the contour), visual (Curvature, Slices, Boxes, Stack: in_blender_visual.py),
surface (Reduce, Smooth Surface: in_blender_surface.py). Any failed case
makes the script exit non-zero.
"""
import argparse
import os
import sys
import traceback

import bpy
import numpy as np

ADDON = "isoform_blender"
ARGS = None


class CaseFailure(Exception):
    pass


def expect(condition, message):
    if not condition:
        raise CaseFailure(message)


def parse_args():
    parser = argparse.ArgumentParser()
    parser.add_argument("group")
    for option in ("--zip", "--data", "--vector-vdb", "--scratch"):
        parser.add_argument(option, required=True)
    parser.add_argument("--expect-vertices", type=int, required=True)
    parser.add_argument("--expect-triangles", type=int, required=True)
    parser.add_argument("--picture", default="")
    return parser.parse_args(sys.argv[sys.argv.index("--") + 1:])


def install_addon():
    """Installs the zip into the temporary user scripts folder and enables it."""
    scripts = os.environ["BLENDER_USER_SCRIPTS"]
    expect(bpy.utils.user_resource('SCRIPTS').startswith(scripts),
           f"user scripts at {bpy.utils.user_resource('SCRIPTS')}, not in {scripts}: refusing")
    bpy.ops.preferences.addon_install(filepath=ARGS.zip, overwrite=True)
    bpy.ops.preferences.addon_enable(module=ADDON)
    module = sys.modules[ADDON]
    expect(module.__file__.startswith(scripts), f"add-on loaded from {module.__file__}")
    from isoform_blender import native
    library = native.library()
    expect(library.path == os.path.join(os.path.dirname(module.__file__), "libisoform.so"),
           f"library loaded from {library.path}, not from the add-on's folder")


def smoke():
    return os.path.join(ARGS.data, "smoke.vdb")


_SMOKE_ARRAYS = []


def smoke_arrays():
    """The library's own contour of smoke.vdb at 0.5 (computed once)."""
    if not _SMOKE_ARRAYS:
        from isoform_blender import native
        _SMOKE_ARRAYS.append(native.contour_file(smoke(), isovalue=0.5))
    return _SMOKE_ARRAYS[0]


def scene_counts():
    return (len(bpy.data.objects), len(bpy.data.meshes), len(bpy.context.scene.objects))


def mesh_arrays(obj):
    """Vertices, triangle corners and the `part` attribute of a mesh object."""
    mesh = obj.data
    points = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", points)
    totals = np.empty(len(mesh.polygons), dtype=np.int32)
    mesh.polygons.foreach_get("loop_total", totals)
    corners = np.empty(len(mesh.loops), dtype=np.int32)
    mesh.loops.foreach_get("vertex_index", corners)
    expect("part" in mesh.attributes, "no `part` attribute")
    part = mesh.attributes["part"]
    expect(part.data_type == 'INT' and part.domain == 'FACE', f"part is {part.data_type} {part.domain}")
    parts = np.empty(len(mesh.polygons), dtype=np.int32)
    part.data.foreach_get("value", parts)
    return points.reshape(-1, 3), totals, corners.reshape(-1, 3), parts


def check_smoke_object(obj, name):
    expect(obj is not None and obj.type == 'MESH' and obj.name == name, f"object {obj}")
    points, totals, corners, parts = mesh_arrays(obj)
    expect(len(points) == ARGS.expect_vertices and len(totals) == ARGS.expect_triangles,
           f"{len(points)} vertices {len(totals)} faces; the CLI gives "
           f"{ARGS.expect_vertices} {ARGS.expect_triangles}")
    expect(np.all(totals == 3), "not all faces are triangles")
    expected = smoke_arrays()
    expect(np.array_equal(points, expected.points), "vertex coordinates differ from the library's")
    expect(np.array_equal(corners, expected.triangles), "triangles differ from the library's")
    expect(np.array_equal(parts, expected.parts), "part ids differ from the library's")
    check_custom_normals(obj.data, corners, expected.normals)


def check_custom_normals(mesh, corners, normals):
    expect(mesh.has_custom_normals, "no custom normals")
    mesh.calc_normals_split()  # Blender 3.4 to 4.0; 4.1 computes corner normals on access
    loop_normals = np.empty(len(mesh.loops) * 3, dtype=np.float32)
    mesh.loops.foreach_get("normal", loop_normals)
    # Custom normals are stored compressed, as angles in each corner's normal
    # space: nearly all within 1e-3, and a few corners (measured on smoke.vdb:
    # 0.2 %) up to 0.8 degrees off.
    cosines = np.einsum("ij,ij->i", loop_normals.reshape(-1, 3), normals[corners.ravel()])
    close = np.mean(np.abs(loop_normals.reshape(-1, 3) - normals[corners.ravel()]).max(axis=1)
                    < 1e-3)
    worst = np.degrees(np.arccos(np.clip(cosines.min(), -1.0, 1.0)))
    expect(close > 0.99 and worst < 2.0,
           f"{close:.2%} of corner normals within 1e-3 of the library's, worst {worst:.2f} deg")


# ---------------------------------------------------------------- import

def case_import_operator_matches_cli():
    before = scene_counts()
    result = bpy.ops.import_scene.isoform_vdb(filepath=smoke(), auto_isovalue=False, isovalue=0.5)
    expect(result == {'FINISHED'}, f"operator returned {result}")
    expect(scene_counts() == tuple(c + 1 for c in before), f"{before} -> {scene_counts()}")
    obj = bpy.context.view_layer.objects.active
    check_smoke_object(obj, "smoke")
    expect(obj.matrix_world == obj.matrix_world.Identity(4), "world coordinates: identity matrix")


def case_blender_mesh_back_to_the_library():
    """The imported mesh, read back with mesh_build.triangle_arrays and given
    to isoform_mesh_from_arrays, is the library's mesh again."""
    from isoform_blender import mesh_build, native
    points, triangles = mesh_build.triangle_arrays(bpy.data.objects["smoke"].data)
    expected = smoke_arrays()
    expect(np.array_equal(points, expected.points), "points differ")
    expect(np.array_equal(triangles, expected.triangles), "triangles differ")
    with native.Mesh.from_arrays(points, triangles) as mesh:
        stats = mesh.stats()
    expect((stats.vertices, stats.triangles, stats.parts, stats.boundary_edges) ==
           (ARGS.expect_vertices, ARGS.expect_triangles, expected.stats.parts, 0), f"stats {stats}")


def case_invoke_in_background_runs_execute():
    result = bpy.ops.import_scene.isoform_vdb('INVOKE_DEFAULT', filepath=smoke(),
                                              auto_isovalue=False, isovalue=0.5)
    expect(result == {'FINISHED'}, f"INVOKE_DEFAULT returned {result}")
    obj = bpy.context.view_layer.objects.active
    expect(len(obj.data.vertices) == ARGS.expect_vertices, f"{len(obj.data.vertices)} vertices")


def case_sidebar_settings_used_when_unset():
    settings = bpy.context.scene.isoform
    settings.auto_isovalue, settings.isovalue, settings.method = False, 0.5, 'tetra'
    try:
        bpy.ops.import_scene.isoform_vdb(filepath=smoke())
    finally:
        settings.auto_isovalue, settings.method = True, 'cells'
    from isoform_blender import native
    expected = native.contour_file(smoke(), isovalue=0.5, method="tetra")
    got = len(bpy.context.view_layer.objects.active.data.polygons)
    expect(got == len(expected.triangles) != ARGS.expect_triangles,
           f"{got} faces; tetra at 0.5 gives {len(expected.triangles)}")


def new_volume_object(name, filepath=""):
    volume = bpy.data.volumes.new(name)
    volume.filepath = filepath
    obj = bpy.data.objects.new(name, volume)
    bpy.context.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    return obj


def case_volume_object_from_file():
    vol = new_volume_object("smoke_volume", smoke())
    vol.location = (10.0, -5.0, 2.0)
    vol.rotation_euler = (0.0, 0.0, 0.5)
    bpy.context.view_layer.update()
    result = bpy.ops.object.isoform_contour(auto_isovalue=False, isovalue=0.5)
    expect(result == {'FINISHED'}, f"operator returned {result}")
    obj = bpy.context.view_layer.objects.active
    check_smoke_object(obj, "smoke_volume_contour")
    expect(obj.matrix_world == vol.matrix_world, "the contour is not where the volume is")


def case_volume_in_memory_saved_to_temporary_file():
    """A volume made by geometry nodes exists only in memory: its evaluated
    grids go through a temporary .vdb (run_blender.py checks none is left)."""
    vol = new_volume_object("cube_volume")
    group = bpy.data.node_groups.new("isoform volume cube", 'GeometryNodeTree')
    group.inputs.new('NodeSocketGeometry', "Geometry")  # Blender 3.4; 4.0 uses group.interface
    group.outputs.new('NodeSocketGeometry', "Geometry")
    cube = group.nodes.new('GeometryNodeVolumeCube')  # density 1 in [-1, 1]^3, 0 outside
    output = group.nodes.new('NodeGroupOutput')
    group.links.new(cube.outputs[0], output.inputs[0])
    vol.modifiers.new("cube", 'NODES').node_group = group
    result = bpy.ops.object.isoform_contour(auto_isovalue=False, isovalue=0.5)
    expect(result == {'FINISHED'}, f"operator returned {result}")
    mesh = bpy.context.view_layer.objects.active.data
    points = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", points)
    points = points.reshape(-1, 3)
    # Crossings lie within one voxel (2/32) of the cube's faces.
    expect(len(points) > 0 and np.all(np.abs(np.abs(points).max(axis=0) - 1.0) < 0.1),
           f"contour of the unit cube spans {points.min(axis=0)}..{points.max(axis=0)}")


# ---------------------------------------------------------------- errors

def head_series_nifti(name, pixdim_x=3.2):
    """The CT head as a 4-D NIfTI in millimetres: volume 0 the scan, volume 1
    half its values; made with nibabel (Blender runs on the system Python)."""
    import nibabel
    raw = np.fromfile(os.path.join(ARGS.data, "headsq_64x64x93_u16le.raw"), dtype="<u2")
    head = raw.reshape(93, 64, 64).transpose(2, 1, 0).astype(np.int16)
    image = nibabel.Nifti1Image(np.stack([head, head // 2], axis=-1),
                                np.diag([3.2, 3.2, 1.5, 1.0]))
    image.header.set_xyzt_units("mm")
    path = os.path.join(ARGS.scratch, name)
    nibabel.save(image, path)
    if pixdim_x != 3.2:  # a damaged copy: pixdim[1] patched in the header
        import struct
        data = bytearray(open(path, "rb").read())
        struct.pack_into("<f", data, 80, pixdim_x)
        open(path, "wb").write(bytes(data))
    return path


def case_scan_import_picks_the_volume_and_metres():
    from isoform_blender import native
    path = head_series_nifti("series.nii")
    expected = native.contour_file(path, volume=1, isovalue=500.0)
    before = scene_counts()
    result = bpy.ops.import_scene.isoform_scan(filepath=path, volume=1, auto_isovalue=False,
                                               isovalue=500.0)
    expect(result == {'FINISHED'}, f"operator returned {result}")
    expect(scene_counts() == tuple(c + 1 for c in before), f"{before} -> {scene_counts()}")
    obj = bpy.context.view_layer.objects.active
    expect(obj.name == "series", obj.name)
    expect(len(obj.data.vertices) == len(expected.points) and len(expected.points) > 1000,
           f"{len(obj.data.vertices)} vertices, the library's contour of volume 1 has "
           f"{len(expected.points)}")
    expect(tuple(obj.scale) == (0.001, 0.001, 0.001) or np.allclose(obj.scale, 0.001),
           f"millimetres to metres: scale {tuple(obj.scale)}")
    volume0 = native.contour_file(path, volume=0, isovalue=500.0)
    expect(len(volume0.points) != len(expected.points), "volume 0 and 1 gave the same contour")
    # Min Part drops the specks: the library's parts of 200 triangles or more, no others.
    sizes = np.bincount(expected.parts)
    result = bpy.ops.import_scene.isoform_scan(filepath=path, volume=1, auto_isovalue=False,
                                               isovalue=500.0, min_part=200)
    expect(result == {'FINISHED'}, f"operator returned {result}")
    kept = bpy.context.view_layer.objects.active
    expect(len(kept.data.polygons) == int(sizes[sizes >= 200].sum()) and (sizes < 200).any(),
           f"{len(kept.data.polygons)} triangles kept; parts of 200 or more hold "
           f"{int(sizes[sizes >= 200].sum())}")


def expect_operator_error(operator, fragments, **properties):
    """The operator must fail with a Blender error report holding every
    fragment, and leave the scene as it was."""
    before = scene_counts()
    try:
        result = operator(**properties)
    except RuntimeError as error:
        message = str(error)
    else:
        raise CaseFailure(f"operator returned {result} instead of failing")
    for fragment in fragments:
        expect(fragment in message, f"report {message!r} lacks {fragment!r}")
    expect(scene_counts() == before, f"scene changed: {before} -> {scene_counts()}")
    return message


def library_message(function):
    from isoform_blender import native
    try:
        function()
    except native.IsoformError as error:
        return str(error)
    raise CaseFailure("the library accepted what the operator should refuse")


def case_missing_file():
    from isoform_blender import native
    missing = os.path.join(ARGS.scratch, "absent.vdb")
    message = library_message(lambda: native.contour_file(missing))
    expect_operator_error(bpy.ops.import_scene.isoform_vdb, [missing, message], filepath=missing)


def case_vector_grid():
    from isoform_blender import native
    first_scalar = library_message(lambda: native.contour_file(ARGS.vector_vdb))
    expect("no scalar grid" in first_scalar, first_scalar)
    expect_operator_error(bpy.ops.import_scene.isoform_vdb, [first_scalar],
                          filepath=ARGS.vector_vdb)
    named = library_message(lambda: native.contour_file(ARGS.vector_vdb, grid="velocity"))
    expect("scalar grids only" in named, named)
    expect_operator_error(bpy.ops.import_scene.isoform_vdb, [named], filepath=ARGS.vector_vdb,
                          grid="velocity")


def case_volume_object_errors():
    new_volume_object("vector_volume", ARGS.vector_vdb)
    expect_operator_error(bpy.ops.object.isoform_contour, ["no scalar grid", "velocity"])
    new_volume_object("empty_volume")
    expect_operator_error(bpy.ops.object.isoform_contour, ["empty_volume", "no grids"])


def case_damaged_scan():
    path = head_series_nifti("damaged.nii", pixdim_x=0.0)
    expect_operator_error(bpy.ops.import_scene.isoform_scan, [path, "pixdim[1], a voxel size, is 0"],
                          filepath=path)


def case_hostile_files():
    """Each hostile VDB through the import operator: an error report naming
    the file, and the scene unchanged. (Not as a Volume object's file: Blender
    then reads the file with its own OpenVDB, which isoform cannot guard.)"""
    import json
    with open(os.path.join(ARGS.scratch, "hostile", "messages.json")) as f:
        files = json.load(f)
    expect(len(files) == 5, f"{len(files)} hostile files")
    for path, message in files.items():
        expect_operator_error(bpy.ops.import_scene.isoform_vdb, [path, message], filepath=path)


# ---------------------------------------------------------------- render

def frame_scene(obj, size, samples):
    """Camera, sun and Cycles CPU settings that show obj whole."""
    from mathutils import Vector
    scene = bpy.context.scene
    corners = [obj.matrix_world @ Vector(c) for c in obj.bound_box]
    centre = sum(corners, Vector()) / 8
    radius = max((c - centre).length for c in corners)
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    camera.location = centre + Vector((1.6, -2.2, 1.0)).normalized() * radius * 2.6
    camera.rotation_euler = (centre - camera.location).to_track_quat('-Z', 'Y').to_euler()
    sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", 'SUN'))
    sun.rotation_euler = (0.7, 0.2, 0.6)
    sun.data.energy = 4.0
    for item in (camera, sun):
        scene.collection.objects.link(item)
    scene.camera = camera
    material = bpy.data.materials.new("smoke")
    material.diffuse_color = (0.8, 0.45, 0.2, 1.0)
    material.use_nodes = True
    material.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (
        0.8, 0.45, 0.2, 1.0)
    obj.data.materials.append(material)
    scene.render.engine = 'CYCLES'
    scene.cycles.device = 'CPU'
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False
    scene.render.resolution_x, scene.render.resolution_y = size
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = 'PNG'
    scene.world.color = (0.05, 0.05, 0.05)


def render_to(path):
    bpy.context.scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(path)
    pixels = np.empty(len(image.pixels), dtype=np.float32)
    image.pixels.foreach_get(pixels)
    width, height = image.size
    return pixels.reshape(height, width, 4)


def case_cycles_render_not_empty():
    bpy.ops.import_scene.isoform_vdb(filepath=smoke(), auto_isovalue=False, isovalue=0.5)
    frame_scene(bpy.context.view_layer.objects.active, (64, 64), 8)
    pixels = render_to(os.path.join(ARGS.scratch, "smoke-64.png"))
    background = pixels[0, 0, :3]
    differs = np.abs(pixels[:, :, :3] - background).max(axis=2) > 0.05
    fraction = differs.mean()
    expect(0.05 < fraction < 0.95, f"{fraction:.1%} of the pixels differ from the background")
    if ARGS.picture:
        bpy.context.scene.render.resolution_x, bpy.context.scene.render.resolution_y = 480, 360
        bpy.context.scene.cycles.samples = 64  # Debian's Blender has no denoiser
        render_to(ARGS.picture)


GROUPS = {
    "import": [case_import_operator_matches_cli, case_blender_mesh_back_to_the_library,
               case_invoke_in_background_runs_execute,
               case_sidebar_settings_used_when_unset, case_volume_object_from_file,
               case_volume_in_memory_saved_to_temporary_file,
               case_scan_import_picks_the_volume_and_metres],
    "errors": [case_missing_file, case_vector_grid, case_volume_object_errors, case_damaged_scan,
               case_hostile_files],
    "render": [case_cycles_render_not_empty],
}


# Groups whose cases live in a module of their own, given this module.
CASE_MODULES = {"visual": "in_blender_visual", "surface": "in_blender_surface"}


def module_cases(group):
    """The cases of in_blender_visual.py (Curvature, Slices, Boxes, Stack) or
    in_blender_surface.py (Reduce, Smooth Surface), given this module."""
    import importlib
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from types import SimpleNamespace
    return importlib.import_module(CASE_MODULES[group]).cases(SimpleNamespace(**globals()))


def main():
    global ARGS
    ARGS = parse_args()
    install_addon()
    if ARGS.group in CASE_MODULES:
        GROUPS[ARGS.group] = module_cases(ARGS.group)
    failures = 0
    for case in GROUPS[ARGS.group]:
        try:
            case()
            print(f"ok   {case.__name__}")
        except Exception:
            failures += 1
            print(f"FAIL {case.__name__}\n{traceback.format_exc()}")
    print(f"{len(GROUPS[ARGS.group]) - failures}/{len(GROUPS[ARGS.group])} cases passed")
    if failures:
        # --python-exit-code turns an uncaught exception into Blender's exit code.
        raise RuntimeError(f"{failures} case(s) failed")


main()
