"""The sidebar tab "isoform" (View3D > Sidebar) and the Object > isoform menu."""
import bpy


class VIEW3D_MT_isoform(bpy.types.Menu):
    bl_idname = "VIEW3D_MT_isoform"
    bl_label = "isoform"

    def draw(self, context):
        self.layout.operator("object.isoform_contour")


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
