"""The contour settings: one set of properties shared by the sidebar (per
scene) and by each operator (so that Adjust Last Operation can change them).

An operator property the caller leaves unset takes the sidebar's value when
the operator runs. SKIP_SAVE keeps Blender from restoring an operator's
last-used values, which would count as set."""
import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, StringProperty

_METHODS = (
    ("cells", "Cells", "Trilinear-consistent cells with the asymptotic decider (Hamann 1991, "
     "Section 3.2)"),
    ("tetra", "Tetrahedra", "Six tetrahedra per cell (Section 3.2)"),
)


class SharedSettings:
    """Mixin: copies the sidebar's values of the names in _SHARED."""
    _SHARED = ()

    def copy_unset_from(self, context):
        """Takes the sidebar's value for every property the caller did not set
        (operators only; called at the start of execute)."""
        scene_settings = getattr(context.scene, "isoform", None)
        if scene_settings is None:
            return
        for name in self._SHARED:
            if not self.properties.is_property_set(name):
                setattr(self, name, getattr(scene_settings, name))


class ContourSettings(SharedSettings):
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


_CURVATURE_METHODS = (
    ("quartic", "Quartic", "Up to quartic terms, three-ring platelet (the most accurate measured)"),
    ("cubic", "Cubic", "Up to cubic terms, two-ring platelet"),
    ("quadric", "Quadric", "Linear and quadratic terms, one-ring platelet"),
    ("seed", "Seed (4.28)", "Three quadratic terms over the one-ring, as Hamann (1991) prints it"),
)
_QUANTITIES = (
    ("mean", "Mean", "H = (k1 + k2) / 2"),
    ("gauss", "Gaussian", "K = k1 k2"),
    ("absolute", "Absolute", "|k1| + |k2|"),
    ("k1", "k1", "The larger principal curvature"),
    ("k2", "k2", "The smaller principal curvature"),
)


class CurvatureSettings(SharedSettings):
    """Mixin: the properties of one curvature call (Section 4.2)."""
    curvature_method: EnumProperty(name="Fit", items=_CURVATURE_METHODS, default="quartic",
                                   options={'SKIP_SAVE'},
                                   description="Height-field fit of each vertex's platelet")
    extra_rings: IntProperty(name="Extra Rings", default=0, min=0, max=8, options={'SKIP_SAVE'},
                             description="Rings added to the fit's platelet: smoother on noisy "
                                         "meshes, less detail")
    color_by: EnumProperty(name="Colour By", items=_QUANTITIES, default="mean",
                           options={'SKIP_SAVE'},
                           description="The quantity the colour attribute shows")

    _SHARED = ("curvature_method", "extra_rings", "color_by")

    def curvature_arguments(self):
        """Keyword arguments of native.Mesh.curvature (plain values)."""
        return {"method": self.curvature_method, "extra_rings": self.extra_rings,
                "color_by": self.color_by}

    def draw_curvature_settings(self, layout):
        layout.prop(self, "curvature_method")
        layout.prop(self, "extra_rings")
        layout.prop(self, "color_by")


class IsoformSettings(bpy.types.PropertyGroup, ContourSettings, CurvatureSettings):
    """The sidebar's settings, stored in the scene as scene.isoform."""
