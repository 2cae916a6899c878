"""The sidebar tab "isoform" (View3D > Sidebar) and the Object > isoform menu."""
import bpy


class VIEW3D_MT_isoform(bpy.types.Menu):
    bl_idname = "VIEW3D_MT_isoform"
    bl_label = "isoform"

    def draw(self, context):
        for name in _OPERATORS:
            self.layout.operator(name)


# Contour, Slices, Boxes, Stack work on a volume object; Curvature, Reduce and
# Smooth Surface on a mesh.
_OPERATORS = ("object.isoform_contour", "object.isoform_slices", "object.isoform_boxes",
              "object.isoform_stack", "object.isoform_curvature", "object.isoform_reduce",
              "object.isoform_smooth")


class VIEW3D_PT_isoform(bpy.types.Panel):
    bl_label = "isoform"
    bl_space_type = 'VIEW_3D'
    bl_region_type = 'UI'
    bl_category = "isoform"

    def draw(self, context):
        layout = self.layout
        settings = context.scene.isoform
        settings.draw_settings(layout.column())
        layout.separator()
        layout.operator("object.isoform_contour", text="Contour Volume", icon='MESH_DATA')
        layout.operator("import_scene.isoform_vdb", text="Import VDB Contour…", icon='IMPORT')
        layout.separator()
        layout.label(text="Volume (Chapter 2)")
        layout.operator("object.isoform_slices", icon='MESH_PLANE')
        layout.operator("object.isoform_boxes", icon='MESH_CUBE')
        layout.operator("object.isoform_stack", icon='MOD_ARRAY')
        layout.separator()
        layout.label(text="Mesh curvature (Section 4.2)")
        settings.draw_curvature_settings(layout.column())
        layout.operator("object.isoform_curvature", icon='SHADING_RENDERED')
        layout.separator()
        layout.label(text="Reduction (Chapter 5)")
        settings.draw_reduce_settings(layout.column())
        layout.operator("object.isoform_reduce", icon='MOD_DECIM')
        layout.separator()
        layout.label(text="Smooth surface (Chapter 6)")
        settings.draw_smooth_settings(layout.column())
        layout.operator("object.isoform_smooth", icon='MOD_SUBSURF')
