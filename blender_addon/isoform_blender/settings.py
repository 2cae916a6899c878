"""The contour settings: one set of properties shared by the sidebar (per
scene) and by each operator (so that Adjust Last Operation can change them).

An operator property the caller leaves unset takes the sidebar's value when
the operator runs. SKIP_SAVE keeps Blender from restoring an operator's
last-used values, which would count as set."""
import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, StringProperty

_METHODS = (
    ("cells", "Cells", "Trilinear-consistent cells with the asymptotic decider (Hamann 1991, "
     "Section 3.2)"),
    ("tetra", "Tetrahedra", "Six tetrahedra per cell (Section 3.2)"),
)


class ContourSettings:
    """Mixin: the properties of one contour call."""
    grid: StringProperty(name="Grid", default="", options={'SKIP_SAVE'},
                         description="Name of the grid to contour; empty: the first scalar grid")
    auto_isovalue: BoolProperty(name="Auto Isovalue", default=True, options={'SKIP_SAVE'},
                                description="Level sets at 0, other grids at the middle of "
                                            "their value range")
    isovalue: FloatProperty(name="Isovalue", default=0.5, precision=4, options={'SKIP_SAVE'},
                            description="Contour level, in the grid's value units")
    method: EnumProperty(name="Method", items=_METHODS, default="cells", options={'SKIP_SAVE'})

    _SHARED = ("grid", "auto_isovalue", "isovalue", "method")

    def copy_unset_from(self, context):
        """Takes the sidebar's value for every property the caller did not set
        (operators only; called at the start of execute)."""
        scene_settings = getattr(context.scene, "isoform", None)
        if scene_settings is None:
            return
        for name in self._SHARED:
            if not self.properties.is_property_set(name):
                setattr(self, name, getattr(scene_settings, name))

    def contour_arguments(self):
        """Keyword arguments of native.contour_file (plain values: thread-safe)."""
        return {"grid": self.grid, "isovalue": None if self.auto_isovalue else self.isovalue,
                "method": self.method}

    def draw_settings(self, layout):
        layout.prop(self, "grid")
        layout.prop(self, "auto_isovalue")
        row = layout.row()
        row.enabled = not self.auto_isovalue
        row.prop(self, "isovalue")
        layout.prop(self, "method")


class IsoformSettings(bpy.types.PropertyGroup, ContourSettings):
    """The sidebar's settings, stored in the scene as scene.isoform."""
