"""isoform for Blender: contours of OpenVDB volumes as meshes.

The package imports no bpy at module level, so that its bpy-free half
(native.py, native_structs.py) can be imported and tested from a plain
Python.
"""
