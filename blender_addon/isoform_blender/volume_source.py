"""A .vdb file on disk holding a Blender volume object's grids."""
import os
import tempfile

import bpy

from .jobs import UserError


def _file_on_disk(obj):
    """The volume's file for the current frame, if Blender reads it unchanged."""
    volume = obj.data
    if obj.modifiers or volume.packed_file is not None:
        return ""  # what Blender shows is not the file on disk
    volume.grids.load()
    path = volume.grids.frame_filepath or volume.filepath
    if not path:
        return ""
    path = bpy.path.abspath(path, library=volume.library)
    return path if os.path.isfile(path) else ""


def _save_evaluated(context, obj):
    # VolumeGrids.save (Blender 2.91 and later, so 3.4 and 4.x alike) writes
    # the evaluated grids, modifiers and geometry nodes applied, as OpenVDB.
    evaluated = obj.evaluated_get(context.evaluated_depsgraph_get())
    grids = evaluated.data.grids
    if len(grids) == 0:
        raise UserError(f"{obj.name}: the volume has no grids"
                        + (f" ({grids.error_message})" if grids.error_message else ""))
    handle, path = tempfile.mkstemp(prefix="isoform-", suffix=".vdb")
    os.close(handle)
    if not grids.save(path) or os.path.getsize(path) == 0:
        os.remove(path)
        raise UserError(f"{obj.name}: Blender could not write its grids to {path}")
    return path


def volume_file(context, obj):
    """(path, temporary): the volume's own file, or its evaluated grids saved
    to a temporary .vdb that the caller removes."""
    path = _file_on_disk(obj)
    if path:
        return path, False
    return _save_evaluated(context, obj), True
