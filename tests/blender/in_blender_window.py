"""The add-on's interactive path: Blender with a window (under Xvfb), where
operators run their work on a worker thread polled from a modal timer.
Run by run_blender.py (group "modal"):

xvfb-run blender --factory-startup --enable-event-simulate --python in_blender_window.py -- ...

The cases run as steps of a bpy.app.timers function, so that Blender's event
loop runs between them; the outcome goes to RESULT_FILE (a window session
has no exit code for failures inside timers).
"""
import argparse
import os
import sys
import time
import traceback

import bpy

ADDON = "isoform_blender"
STEP_SECONDS = 0.2
CASE_TIMEOUT_SECONDS = 240


def parse_args():
    parser = argparse.ArgumentParser()
    parser.add_argument("group")
    for option in ("--zip", "--data", "--vector-vdb", "--scratch"):
        parser.add_argument(option, required=True)
    parser.add_argument("--expect-vertices", type=int, required=True)
    parser.add_argument("--expect-triangles", type=int, required=True)
    parser.add_argument("--picture", default="")
    return parser.parse_args(sys.argv[sys.argv.index("--") + 1:])


ARGS = parse_args()
RESULT_FILE = os.path.join(ARGS.scratch, "window-result.txt")
STARTED_JOBS = []


def install_addon():
    scripts = os.environ["BLENDER_USER_SCRIPTS"]
    assert bpy.utils.user_resource('SCRIPTS').startswith(scripts), "not a temporary user folder"
    bpy.ops.preferences.addon_install(filepath=ARGS.zip, overwrite=True)
    bpy.ops.preferences.addon_enable(module=ADDON)
    # Record every worker job the operators start (test introspection only).
    from isoform_blender import jobs
    start = jobs.Job.start

    def recording_start(job):
        STARTED_JOBS.append(job)
        start(job)
    jobs.Job.start = recording_start


def view3d_override():
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == 'VIEW_3D')
    region = next(r for r in area.regions if r.type == 'WINDOW')
    return {"window": window, "screen": window.screen, "area": area, "region": region}


def invoke(operator, **properties):
    with bpy.context.temp_override(**view3d_override()):
        return operator('INVOKE_DEFAULT', **properties)


def object_names():
    return sorted(o.name for o in bpy.data.objects)


# Each case is a generator: it yields to let Blender run, and fails by assert.

def case_import_runs_on_a_worker_thread():
    before = object_names()
    result = invoke(bpy.ops.import_scene.isoform_vdb, filepath=os.path.join(ARGS.data, "smoke.vdb"),
                    auto_isovalue=False, isovalue=0.5)
    assert result == {'RUNNING_MODAL'}, f"invoke returned {result}"
    assert len(STARTED_JOBS) == 1, "no worker job started"
    assert object_names() == before, "the scene changed before the job ended"
    while "smoke" not in bpy.data.objects:
        yield
    mesh = bpy.data.objects["smoke"].data
    assert (len(mesh.vertices), len(mesh.polygons)) == (ARGS.expect_vertices, ARGS.expect_triangles), \
        f"{len(mesh.vertices)} vertices {len(mesh.polygons)} faces"
    assert STARTED_JOBS[-1].progress.stage_name == "done", STARTED_JOBS[-1].progress.stage_name
    yield
    # One undo step (REGISTER and UNDO, pushed when the modal operator ends).
    with bpy.context.temp_override(**view3d_override()):
        bpy.ops.ed.undo()
    assert object_names() == before, f"after undo: {object_names()}, before: {before}"
    with bpy.context.temp_override(**view3d_override()):
        bpy.ops.ed.redo()
    assert "smoke" in object_names(), f"after redo: {object_names()}"


def file_browser():
    """The window, area and region of the open file browser, if any."""
    for window in bpy.context.window_manager.windows:
        for area in window.screen.areas:
            if area.type == 'FILE_BROWSER':
                region = next(r for r in area.regions if r.type == 'WINDOW')
                return {"window": window, "screen": window.screen, "area": area, "region": region}
    return None


def case_file_browser_path():
    """File > Import as a user does it: the file browser opens, a file is
    confirmed, execute() then runs the work on a worker thread."""
    before = object_names()
    jobs_before = len(STARTED_JOBS)
    result = invoke(bpy.ops.import_scene.isoform_vdb)
    assert result == {'RUNNING_MODAL'}, f"invoke returned {result}"
    while file_browser() is None:
        yield
    browser = file_browser()
    params = browser["area"].spaces.active.params
    params.directory = ARGS.data.encode()  # bytes in Blender 3.4
    params.filename = "sphere.vdb"
    yield
    with bpy.context.temp_override(**browser):
        bpy.ops.file.execute()
    while "sphere" not in bpy.data.objects:
        yield
    assert len(STARTED_JOBS) == jobs_before + 1, "the work did not run on a worker job"
    assert len(bpy.data.objects["sphere"].data.vertices) > 0, "empty sphere"
    yield
    with bpy.context.temp_override(**view3d_override()):
        bpy.ops.ed.undo()
    assert object_names() == before, f"after undo: {object_names()}, before: {before}"


def case_escape_cancels():
    from isoform_blender import native
    before = object_names()
    result = invoke(bpy.ops.import_scene.isoform_vdb, filepath=os.path.join(ARGS.data, "cube.vdb"),
                    method='tetra')
    assert result == {'RUNNING_MODAL'}, f"invoke returned {result}"
    job = STARTED_JOBS[-1]
    # Queued now, so that the operator's modal handler sees it while the job runs.
    bpy.context.window_manager.windows[0].event_simulate(type='ESC', value='PRESS')
    while not job.done:
        yield
    for _ in range(5):  # let the modal handler see the end
        yield
    assert job.progress.cancelled, "Esc did not set the cancel flag"
    assert object_names() == before, f"objects {before} -> {object_names()}"
    # Cancelled by the library (Esc during loading or contouring) or dropped
    # by the operator (Esc during a later stage): either way nothing was added.
    assert job.error is None or isinstance(job.error, native.CancelledError), repr(job.error)


def case_worker_error_reported():
    """A vector grid fails on the worker thread; its message (thread-local
    in the library) reaches the job, and nothing is added."""
    before = object_names()
    result = invoke(bpy.ops.import_scene.isoform_vdb, filepath=ARGS.vector_vdb, grid="velocity")
    assert result == {'RUNNING_MODAL'}, f"invoke returned {result}"
    job = STARTED_JOBS[-1]
    while not job.done:
        yield
    for _ in range(5):
        yield
    assert "scalar grids only" in str(job.error), repr(job.error)
    assert object_names() == before, f"objects {before} -> {object_names()}"


def case_volume_in_memory_cleans_up():
    volume = bpy.data.volumes.new("cube_volume")
    obj = bpy.data.objects.new("cube_volume", volume)
    bpy.context.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    group = bpy.data.node_groups.new("isoform volume cube", 'GeometryNodeTree')
    group.outputs.new('NodeSocketGeometry', "Geometry")  # Blender 3.4; 4.0 uses group.interface
    cube = group.nodes.new('GeometryNodeVolumeCube')
    group.links.new(cube.outputs[0], group.nodes.new('NodeGroupOutput').inputs[0])
    obj.modifiers.new("cube", 'NODES').node_group = group
    temporary = os.environ["TMPDIR"]
    result = invoke(bpy.ops.object.isoform_contour, auto_isovalue=False, isovalue=0.5)
    assert result == {'RUNNING_MODAL'}, f"invoke returned {result}"
    assert any(n.startswith("isoform-") for n in os.listdir(temporary)), "no temporary .vdb"
    while "cube_volume_contour" not in bpy.data.objects:
        yield
    assert len(bpy.data.objects["cube_volume_contour"].data.vertices) > 0, "empty contour"
    leftovers = [n for n in os.listdir(temporary) if n.startswith("isoform-")]
    assert not leftovers, f"temporary files left: {leftovers}"


def case_curvature_and_stack_from_the_view():
    """Curvature runs on a worker thread; Stack invoked from the 3D view sorts
    for that view's direction (the same order as the library's for it)."""
    import numpy as np
    from mathutils import Vector
    from isoform_blender import native, native_visualize
    bpy.ops.mesh.primitive_ico_sphere_add(radius=1.0, subdivisions=3)
    sphere = bpy.context.view_layer.objects.active
    jobs_before = len(STARTED_JOBS)
    result = invoke(bpy.ops.object.isoform_curvature)
    assert result == {'RUNNING_MODAL'}, f"invoke returned {result}"
    assert len(STARTED_JOBS) == jobs_before + 1, "no worker job started"
    while "mean" not in sphere.data.attributes:
        yield
    volume = bpy.data.objects.new("smoke_view", bpy.data.volumes.new("smoke_view"))
    volume.data.filepath = os.path.join(ARGS.data, "smoke.vdb")
    bpy.context.collection.objects.link(volume)
    bpy.context.view_layer.objects.active = volume
    region = view3d_override()["area"].spaces.active.region_3d
    view = region.view_rotation @ Vector((0.0, 0.0, -1.0))
    result = invoke(bpy.ops.object.isoform_stack, n=(2, 2, 2))
    assert result == {'RUNNING_MODAL'}, f"invoke returned {result}"
    while "smoke_view_stack" not in bpy.data.objects:
        yield
    mesh = bpy.data.objects["smoke_view_stack"].data
    points = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", points)
    with native.Volume.open(volume.data.filepath) as handle:
        expected = native_visualize.coloured_arrays(native_visualize.stack(
            handle, "", n=(2, 2, 2), view=tuple(view)))
        default = native_visualize.coloured_arrays(native_visualize.stack(handle, "", n=(2, 2, 2)))
    assert not np.allclose(default.points, expected.points), "the view changes nothing here"
    assert np.allclose(points.reshape(-1, 3), expected.points, atol=1e-5), \
        f"the stack is not sorted for the view {tuple(view)}"


CASES = [case_import_runs_on_a_worker_thread, case_file_browser_path, case_escape_cancels,
         case_worker_error_reported, case_volume_in_memory_cleans_up,
         case_curvature_and_stack_from_the_view]


def run_cases():
    """Drives the case generators from a timer; writes the result, quits."""
    lines = []
    for case in CASES:
        started = time.time()
        try:
            steps = case()
            for _ in steps:
                assert time.time() - started < CASE_TIMEOUT_SECONDS, "timed out"
                yield
            lines.append(f"ok   {case.__name__}")
        except Exception:
            lines.append(f"FAIL {case.__name__}\n{traceback.format_exc()}")
    with open(RESULT_FILE, "w") as out:
        out.write("\n".join(lines) + "\n")


def main():
    install_addon()
    runner = run_cases()

    def tick():
        try:
            next(runner)
            return STEP_SECONDS
        except StopIteration:
            bpy.ops.wm.quit_blender()
            return None
    bpy.app.timers.register(tick, first_interval=1.0)


main()
