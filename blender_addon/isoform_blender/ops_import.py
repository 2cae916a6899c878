"""File > Import > VDB Contour (.vdb) and Scan Contour (.nii, .nii.gz,
.nrrd, .nhdr): a volume file's contour as a mesh."""
import os

import bpy
from bpy.props import BoolProperty, IntProperty, StringProperty
from bpy_extras.io_utils import ImportHelper

from .jobs import JobOperator
from .settings import ContourSettings

# Blender's unit is the metre: a scan's unit becomes one by the object's scale.
_METRES_PER_UNIT = {"mm": 0.001, "um": 1e-6, "m": 1.0}


class _ContourImport(ImportHelper, ContourSettings, JobOperator):
    """Mixin: a file browser, the contour settings, the contour as a new object."""

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

    def file_arguments(self):
        """What native.contour_file needs besides the contour settings."""
        return {}

    def prepare(self, context):
        from . import native
        path = bpy.path.abspath(self.filepath)
        arguments = dict(self.contour_arguments(), **self.file_arguments())
        name = os.path.basename(path)
        for ext in (".gz", ".vdb", ".nii", ".nrrd", ".nhdr", ".hdr"):
            if name.lower().endswith(ext):
                name = name[:-len(ext)]
        self._object_name = name or "contour"
        return lambda progress: native.contour_file(path, progress=progress, **arguments)

    def object_scale(self, arrays):
        return 1.0

    def finish(self, context, arrays):
        from . import mesh_build
        # The library writes world coordinates: the object keeps them, scaled
        # only to bring a file's unit to Blender's metres where asked.
        obj = mesh_build.add_mesh_object(context, self._object_name, arrays)
        scale = self.object_scale(arrays)
        obj.scale = (scale, scale, scale)


class IMPORT_SCENE_OT_isoform_vdb(bpy.types.Operator, _ContourImport):
    """Contour a grid of an OpenVDB file into a mesh in world coordinates"""
    bl_idname = "import_scene.isoform_vdb"
    bl_label = "Import VDB Contour"
    bl_options = {'REGISTER', 'UNDO'}

    filename_ext = ".vdb"
    filter_glob: StringProperty(default="*.vdb", options={'HIDDEN'})


class IMPORT_SCENE_OT_isoform_scan(bpy.types.Operator, _ContourImport):
    """Contour a CT or MRI scan (NIfTI or NRRD) into a mesh in the scan's world coordinates"""
    bl_idname = "import_scene.isoform_scan"
    bl_label = "Import Scan Contour"
    bl_options = {'REGISTER', 'UNDO'}

    filename_ext = ".nii.gz"
    filter_glob: StringProperty(default="*.nii;*.nii.gz;*.hdr;*.nrrd;*.nhdr", options={'HIDDEN'})
    volume: IntProperty(name="Volume", default=0, min=0, options={'SKIP_SAVE'},
                        description="The volume (from 0) of a 4-D NIfTI file, such as one time "
                                    "point of a series")
    to_metres: BoolProperty(name="File Units to Metres", default=True, options={'SKIP_SAVE'},
                            description="Scale the object so that the scan's unit (mm, um) "
                                        "becomes metres, Blender's unit")

    def draw(self, context):
        super().draw(context)
        self.layout.prop(self, "volume")
        self.layout.prop(self, "to_metres")

    def file_arguments(self):
        return {"volume": self.volume}

    def object_scale(self, arrays):
        return _METRES_PER_UNIT.get(arrays.unit, 1.0) if self.to_metres else 1.0
