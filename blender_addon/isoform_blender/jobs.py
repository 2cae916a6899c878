"""Long library calls on a worker thread, polled from a modal timer.

An operator using JobOperator splits its work in three:
- prepare(context) on the main thread reads Blender data and returns
  work(progress), a function of plain values only (no bpy: Blender's data
  must not be touched off the main thread);
- work runs on a worker thread with a native.Progress the timer polls
  (fraction and stage in the status bar; Esc sets its cancel flag);
- finish(context, result) on the main thread builds Blender data.
In background mode, and when Blender calls execute() on its own (redo,
scripts), work runs synchronously on the calling thread instead.
"""
import threading

import bpy

TIMER_SECONDS = 0.1


class UserError(Exception):
    """A problem with the user's input found on the Blender side."""


class Job:
    """work(progress) on a daemon thread; keeps its result or its exception."""

    def __init__(self, work, progress):
        self.progress = progress
        self.result = None
        self.error = None
        self._work = work
        self._thread = threading.Thread(target=self._run, name="isoform job", daemon=True)

    def start(self):
        self._thread.start()

    def _run(self):
        try:
            self.result = self._work(self.progress)
        except Exception as error:  # handed to the main thread, reported there
            self.error = error

    @property
    def done(self):
        return not self._thread.is_alive()


class JobOperator:
    """Mixin for operators whose work is one long library call."""

    # The two steps every operator using this mixin defines (abstract here).
    def prepare(self, context):
        """Reads the operator's inputs on the main thread; returns work(progress)."""
        raise NotImplementedError(type(self).__name__ + " must define prepare()")

    def finish(self, context, result):
        """Turns the work's result into Blender data on the main thread."""
        raise NotImplementedError(type(self).__name__ + " must define finish()")

    def cleanup(self):
        """Runs once at the end, whatever happened (temporary files)."""

    def mark_interactive(self):
        """Called from invoke(): execute() may then run the work in the background."""
        self._interactive = True

    def copy_unset_from(self, context):
        """Settings mixins (settings.SharedSettings) take the sidebar's values here."""

    # NOTE: Blender calls invoke() only with a window; in background mode
    # INVOKE_DEFAULT goes straight to execute(), which then runs synchronously.
    def invoke(self, context, event):
        self.mark_interactive()
        return self.execute(context)

    def execute(self, context):
        self.copy_unset_from(context)
        return self.run(context)

    def run(self, context):
        """The body of execute()."""
        from . import native
        try:
            work = self.prepare(context)
        except (UserError, native.IsoformError, native.LibraryError, ValueError) as error:
            self.cleanup()
            return self._fail(error)
        if not self._runs_in_background(context):
            return self._complete(context, work, None)
        self._job = Job(work, native.Progress())
        self._job.start()
        wm = context.window_manager
        self._timer = wm.event_timer_add(TIMER_SECONDS, window=context.window)
        wm.modal_handler_add(self)
        wm.progress_begin(0.0, 1.0)
        return {'RUNNING_MODAL'}

    def _runs_in_background(self, context):
        return (getattr(self, "_interactive", False) and not bpy.app.background
                and context.window is not None)

    def modal(self, context, event):
        if event.type == 'ESC' and event.value == 'PRESS':
            self._job.progress.cancel()
            return {'RUNNING_MODAL'}
        if event.type != 'TIMER':
            return {'PASS_THROUGH'}
        if not self._job.done:
            progress = self._job.progress
            context.window_manager.progress_update(progress.fraction)
            context.workspace.status_text_set(
                f"isoform: {progress.stage_name} {progress.fraction:.0%} (Esc cancels)")
            return {'PASS_THROUGH'}
        self._stop_polling(context)
        job = self._job
        return self._complete(context, lambda progress: _result_of(job), None)

    def _stop_polling(self, context):
        wm = context.window_manager
        wm.event_timer_remove(self._timer)
        wm.progress_end()
        context.workspace.status_text_set(None)

    def _complete(self, context, work, progress):
        from . import native
        try:
            result = work(progress)
            self.finish(context, result)
        except native.CancelledError:
            self.report({'WARNING'}, "isoform: cancelled; nothing was changed")
            return {'CANCELLED'}
        except (UserError, native.IsoformError, native.LibraryError, ValueError) as error:
            return self._fail(error)
        finally:
            self.cleanup()
        return {'FINISHED'}

    def _fail(self, error):
        self.report({'ERROR'}, str(error))
        return {'CANCELLED'}


def _result_of(job):
    from . import native
    if job.error is not None:
        raise job.error
    # NOTE: the library polls the cancel flag only while it contours cells;
    # Esc pressed during a later stage (merge, topology) drops the result here.
    if job.progress.cancelled:
        raise native.CancelledError("cancelled")
    return job.result


class MeshJobOperator(JobOperator):
    """A JobOperator on the active mesh object, in Object Mode."""

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == 'MESH' and context.mode == 'OBJECT'

