"""Object > isoform > Contour: the selected volume's contour as a mesh beside it."""
import os

import bpy

from .jobs import JobOperator
from .settings import ContourSettings


class OBJECT_OT_isoform_contour(bpy.types.Operator, ContourSettings, JobOperator):
    """Contour the active volume object into a mesh at the same place"""
    bl_idname = "object.isoform_contour"
    bl_label = "Contour"
    bl_options = {'REGISTER', 'UNDO'}

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == 'VOLUME'

    def draw(self, context):
        self.draw_settings(self.layout)

    def prepare(self, context):
        from . import native, volume_source
        obj = context.active_object
        path, self._temporary = volume_source.volume_file(context, obj)
        self._path = path
        self._object_name = f"{obj.name}_contour"
        # The grids' transform is the volume's object space: keep its placement.
        self._matrix = obj.matrix_world.copy()
        arguments = self.contour_arguments()
        return lambda progress: native.contour_file(path, progress=progress, **arguments)

    def finish(self, context, arrays):
        from . import mesh_build
        mesh_build.add_mesh_object(context, self._object_name, arrays, self._matrix)

    def cleanup(self):
        if getattr(self, "_temporary", False) and os.path.exists(self._path):
            os.remove(self._path)
        self._temporary = False
