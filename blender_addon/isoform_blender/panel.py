"""The sidebar tab "isoform" (View3D > Sidebar) and the Object > isoform menu."""
import bpy


class VIEW3D_MT_isoform(bpy.types.Menu):
    bl_idname = "VIEW3D_MT_isoform"
    bl_label = "isoform"

    def draw(self, context):
        for name in _OPERATORS:
            self.layout.operator(name)


# Contour, Slices, Boxes, Stack work on a volume object; Curvature, Reduce,
# Smooth Surface and Compare on a mesh.
_OPERATORS = ("object.isoform_contour", "object.isoform_slices", "object.isoform_boxes",
              "object.isoform_stack", "object.isoform_curvature", "object.isoform_reduce",
              "object.isoform_smooth", "object.isoform_compare")


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
        layout.separator()
        layout.label(text="Comparison with Loop subdivision")
        settings.draw_compare_settings(layout.column())
        layout.operator("object.isoform_compare", icon='MOD_SMOOTH')
        _draw_comparison(layout, context.active_object)


def _draw_comparison(layout, obj):
    """The measures stored by Compare for the active object, one row per surface."""
    from . import ops_compare
    name, stored = ops_compare.stored_comparison(obj)
    if stored is None:
        return
    box = layout.box()
    box.label(text=f"{name}: reference {stored['reference'] or 'none'}")
    grid = box.grid_flow(columns=4, even_columns=False, align=True)
    for heading in ("surface", "gap max", "H jump", "data err"):
        grid.label(text=heading)
    for surface, gap, jump, error, _ in ops_compare.rows(stored):
        grid.label(text=surface)
        grid.label(text=f"{gap:.2g} deg")
        grid.label(text=f"{jump:.3g}")
        grid.label(text=f"{error:.3g}")
    for surface, _, _, _, deviation in ops_compare.rows(stored):
        if deviation is not None:
            box.label(text=f"{surface}: deviation RMS {deviation:.3g} {stored['unit']}")
