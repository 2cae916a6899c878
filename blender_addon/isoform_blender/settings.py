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
    min_part: IntProperty(name="Min Part", default=0, min=0, options={'SKIP_SAVE'},
                          description="Drop parts of fewer triangles (a noisy scan's specks); "
                                      "0 keeps all")

    _SHARED = ("grid", "auto_isovalue", "isovalue", "method", "min_part")

    def contour_arguments(self):
        """Keyword arguments of native.contour_file (plain values: thread-safe)."""
        return {"grid": self.grid, "isovalue": None if self.auto_isovalue else self.isovalue,
                "method": self.method, "min_part": self.min_part}

    def draw_settings(self, layout):
        layout.prop(self, "grid")
        layout.prop(self, "auto_isovalue")
        row = layout.row()
        row.enabled = not self.auto_isovalue
        row.prop(self, "isovalue")
        layout.prop(self, "method")
        layout.prop(self, "min_part")


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




_REDUCE_POINTS = (
    ("quadratic", "Quadratic", "Bivariate quadratic least squares in the triangle's plane "
     "(Hamann 1991, 5.26-5.29)"),
    ("quadric", "Quadric", "Implicit quadric through the platelet (5.30-5.33)"),
)


class ReduceSettings(SharedSettings):
    """Mixin: the properties of one reduction (Chapter 5)."""
    keep_percent: FloatProperty(name="Keep", default=10.0, min=0.01, max=100.0, precision=2,
                                subtype='PERCENTAGE', options={'SKIP_SAVE'},
                                description="Percentage of the triangles to keep")
    use_tolerance: BoolProperty(name="Tolerance", default=False, options={'SKIP_SAVE'},
                                description="Also stop removing where the surface would move "
                                            "farther than the tolerance")
    tolerance: FloatProperty(name="Distance", default=0.01, min=0.0, precision=5,
                             subtype='DISTANCE', options={'SKIP_SAVE'},
                             description="Largest distance of an original vertex from the "
                                         "reduced surface, in world units")
    lock_boundary: BoolProperty(name="Lock Boundary", default=False, options={'SKIP_SAVE'},
                                description="Keep every boundary vertex (open meshes)")
    prevent_overlap: BoolProperty(name="No Overlap", default=False, options={'SKIP_SAVE'},
                                  description="Refuse a removal whose new triangles would cross "
                                              "the rest of the mesh (slower; for thin walls and "
                                              "close sheets)")
    height_field: BoolProperty(name="Height Field", default=False, options={'SKIP_SAVE'},
                               description="The mesh is a height field z = f(x, y) in world "
                                           "space (a terrain; every face counterclockwise "
                                           "seen from above): its (x, y) outline stays "
                                           "covered and new points move vertically")
    reduce_point: EnumProperty(name="Point", items=_REDUCE_POINTS, default="quadratic",
                               options={'SKIP_SAVE'},
                               description="How the point replacing a triangle is made")

    _SHARED = ("keep_percent", "use_tolerance", "tolerance", "lock_boundary", "prevent_overlap",
               "height_field", "reduce_point")

    def reduce_arguments(self):
        """Keyword arguments of native_surface.reduce (plain values)."""
        return {"keep_fraction": self.keep_percent / 100.0,
                "tolerance": self.tolerance if self.use_tolerance else 0.0,
                "lock_boundary": self.lock_boundary, "point": self.reduce_point,
                "prevent_overlap": self.prevent_overlap, "height_field": self.height_field}

    def draw_reduce_settings(self, layout):
        layout.prop(self, "keep_percent")
        row = layout.row(align=True)
        row.prop(self, "use_tolerance")
        sub = row.row()
        sub.enabled = self.use_tolerance
        sub.prop(self, "tolerance", text="")
        layout.prop(self, "lock_boundary")
        layout.prop(self, "prevent_overlap")
        layout.prop(self, "height_field")
        layout.prop(self, "reduce_point")


_BLENDS = (
    ("squared", "Squared", "Weights (u_j u_k)^2, which satisfy Theorem 6.1 (iii)"),
    ("printed", "Printed (6.2)", "Weights u_j u_k as Hamann (1991) prints them"),
)
_NORMAL_SOURCES = (
    ("MESH", "Mesh", "The mesh's own vertex normals (a contour import carries the volume's "
     "gradient normals)"),
    ("ESTIMATE", "Estimate", "Normals estimated from the triangles by the library"),
)


class SmoothSettings(SharedSettings):
    """Mixin: the properties of one side-vertex surface (Chapter 6)."""
    level: IntProperty(name="Level", default=3, min=0, max=6, options={'SKIP_SAVE'},
                       description="Each triangle becomes 4^level triangles")
    blend: EnumProperty(name="Blend", items=_BLENDS, default="squared", options={'SKIP_SAVE'})
    auto_tension: BoolProperty(name="Automatic Tension", default=True, options={'SKIP_SAVE'},
                               description="Conic weights sin(gamma/2) (Theorem 6.3)")
    tension: FloatProperty(name="Tension", default=0.5, min=0.001, max=1.0, precision=3,
                           options={'SKIP_SAVE'},
                           description="One conic weight for every edge: lower pulls the "
                                       "surface toward the triangles")
    normal_source: EnumProperty(name="Normals", items=_NORMAL_SOURCES, default="MESH",
                                options={'SKIP_SAVE'})

    _SHARED = ("level", "blend", "auto_tension", "tension", "normal_source")

    def patch_arguments(self):
        """Keyword arguments of native_surface.Patch.create (plain values)."""
        return {"blend": self.blend, "tension": 0.0 if self.auto_tension else self.tension}

    def draw_smooth_settings(self, layout):
        layout.prop(self, "level")
        layout.prop(self, "blend")
        layout.prop(self, "normal_source")
        layout.prop(self, "auto_tension")
        row = layout.row()
        row.enabled = not self.auto_tension
        row.prop(self, "tension")


_REFERENCES = (
    ("none", "None", "No reference surface: smoothness measures only"),
    ("sphere", "Sphere", "Deviation from the sphere fitted to the vertices"),
    ("torus", "Torus", "Deviation from the torus around the z axis fitted to the vertices"),
)


class CompareSettings(SharedSettings):
    """Mixin: the properties of one comparison with the Loop limit surface."""
    compare_level: IntProperty(name="Samples", default=8, min=1, max=32, options={'SKIP_SAVE'},
                               description="Lattice level k: (k+1)(k+2)/2 samples per triangle "
                                           "on every surface, k^2 triangles in the Loop object")
    reference: EnumProperty(name="Reference", items=_REFERENCES, default="none",
                            options={'SKIP_SAVE'})

    _SHARED = ("compare_level", "reference")

    def compare_arguments(self):
        """Keyword arguments of native_surface.compare (plain values)."""
        return {"level": self.compare_level, "reference": self.reference}

    def draw_compare_settings(self, layout):
        layout.prop(self, "compare_level")
        layout.prop(self, "reference")


class IsoformSettings(bpy.types.PropertyGroup, ContourSettings, CurvatureSettings,
                      ReduceSettings, SmoothSettings, CompareSettings):
    """The sidebar's settings, stored in the scene as scene.isoform."""
