"""PRT as a render engine in Blender: F12 (and Ctrl-F12) renders the open scene with `prt
render` on this machine, MPI hosts, a Slurm cluster, or with machines that join, the image
filling in as prt renders it. docs/blender.md says how to install and use it.

bpy is imported by the submodules that need it, when Blender registers the add-on, so that
the command-line modules (commands, process) can be used and tested without Blender.
"""

bl_info = {
    "name": "PRT render engine",
    "author": "PRT developers",
    "version": (1, 0, 0),
    "blender": (3, 4, 0),
    "location": "Render properties > Render Engine > PRT",
    "description": "Renders with PRT, the parallel ray tracer, on this machine, MPI hosts or "
                   "a Slurm cluster",
    "category": "Render",
}


def register():
    from . import engine, panels, properties
    properties.register()
    engine.register()
    panels.register()


def unregister():
    from . import engine, panels, properties
    panels.unregister()
    engine.unregister()
    properties.unregister()
