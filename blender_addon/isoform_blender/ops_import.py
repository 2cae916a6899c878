"""File > Import > VDB Contour (.vdb): a volume file's contour as a mesh."""
import os

import bpy
from bpy.props import StringProperty
from bpy_extras.io_utils import ImportHelper

from .jobs import JobOperator
from .settings import ContourSettings


class IMPORT_SCENE_OT_isoform_vdb(bpy.types.Operator, ImportHelper, ContourSettings, JobOperator):
    """Contour a grid of an OpenVDB file into a mesh in world coordinates"""
    bl_idname = "import_scene.isoform_vdb"
    bl_label = "Import VDB Contour"
    bl_options = {'REGISTER', 'UNDO'}

    filename_ext = ".vdb"
    filter_glob: StringProperty(default="*.vdb", options={'HIDDEN'})

    def draw(self, context):
        self.draw_settings(self.layout)

    # NOTE: Blender calls invoke() only with a window; in background mode
    # INVOKE_DEFAULT goes straight to execute(), which then runs synchronously.
    def invoke(self, context, event):
        self.mark_interactive()
        self.copy_unset_from(context)  # the file browser then shows the sidebar's values
        if self.properties.is_property_set("filepath"):
            return self.execute(context)
        return ImportHelper.invoke(self, context, event)

    def prepare(self, context):
        from . import native
        path = bpy.path.abspath(self.filepath)
        arguments = self.contour_arguments()
        self._object_name = os.path.splitext(os.path.basename(path))[0] or "contour"
        return lambda progress: native.contour_file(path, progress=progress, **arguments)

    def finish(self, context, arrays):
        from . import mesh_build
        # The library writes world coordinates: the object keeps the identity.
        mesh_build.add_mesh_object(context, self._object_name, arrays)
