"""isoform for Blender: contours of OpenVDB volumes as meshes.

The package imports no bpy at module level, so that its bpy-free half
(native.py, native_structs.py) can be imported and tested from a plain
Python. Blender calls register(), which loads the operators and panels.
"""

# Read by Blender 3.4 to 4.1 (legacy add-ons); Blender 4.2 and later read
# blender_manifest.toml instead and ignore this.
bl_info = {
    "name": "isoform",
    "author": "isoform",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > VDB Contour; Object > isoform; View3D > Sidebar > isoform",
    "description": "Watertight contours (isosurfaces) of OpenVDB volumes, after Hamann (1991)",
    "category": "Import-Export",
}


def register():
    from . import registration
    registration.register()


def unregister():
    from . import registration
    registration.unregister()
