"""Registers the add-on's classes and menu entries (bpy only here and below)."""
import bpy

from . import (ops_compare, ops_curvature, ops_import, ops_reduce, ops_smooth, ops_visualize,
               ops_volume, panel, settings)

_CLASSES = (
    settings.IsoformSettings,
    ops_import.IMPORT_SCENE_OT_isoform_vdb,
    ops_import.IMPORT_SCENE_OT_isoform_scan,
    ops_volume.OBJECT_OT_isoform_contour,
    ops_curvature.OBJECT_OT_isoform_curvature,
    ops_reduce.OBJECT_OT_isoform_reduce,
    ops_smooth.OBJECT_OT_isoform_smooth,
    ops_compare.OBJECT_OT_isoform_compare,
    ops_visualize.OBJECT_OT_isoform_slices,
    ops_visualize.OBJECT_OT_isoform_boxes,
    ops_visualize.OBJECT_OT_isoform_stack,
    panel.VIEW3D_MT_isoform,
    panel.VIEW3D_PT_isoform,
)


def _import_menu(self, context):
    self.layout.operator(ops_import.IMPORT_SCENE_OT_isoform_vdb.bl_idname,
                         text="VDB Contour (.vdb)")
    self.layout.operator(ops_import.IMPORT_SCENE_OT_isoform_scan.bl_idname,
                         text="Scan Contour (.nii, .nii.gz, .nrrd)")


def _object_menu(self, context):
    self.layout.menu(panel.VIEW3D_MT_isoform.bl_idname)


def register():
    for cls in _CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.isoform = bpy.props.PointerProperty(type=settings.IsoformSettings)
    bpy.types.TOPBAR_MT_file_import.append(_import_menu)
    bpy.types.VIEW3D_MT_object.append(_object_menu)


def unregister():
    bpy.types.VIEW3D_MT_object.remove(_object_menu)
    bpy.types.TOPBAR_MT_file_import.remove(_import_menu)
    del bpy.types.Scene.isoform
    for cls in reversed(_CLASSES):
        bpy.utils.unregister_class(cls)
