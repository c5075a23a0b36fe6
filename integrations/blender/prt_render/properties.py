"""PRT's settings on each scene (scene.prt), with prt's names and defaults."""
import bpy

from . import commands


def _strategy_items():
    return [(name, name, "prt render --strategy %s%s"
             % (name, " (prt's default)" if name == commands.DEFAULT_STRATEGY else ""))
            for name in commands.STRATEGIES]


class PRTRenderSettings(bpy.types.PropertyGroup):
    prt_path: bpy.props.StringProperty(
        name="prt", default="prt", subtype='FILE_PATH',
        description="The prt executable: a path, or a name looked up on PATH")
    integrator: bpy.props.EnumProperty(
        name="Integrator", default="path",
        items=[("path", "Path tracer", "The physically based path tracer (glTF materials as "
                "Blender's Principled BSDF gives them)"),
               ("hall", "Hall", "The paper's Whitted ray tracer with Hall's shading model")])
    samples: bpy.props.IntProperty(
        name="Samples", default=16, min=1, max=4096,
        description="Samples per pixel (prt render --spp)")
    where: bpy.props.EnumProperty(
        name="Render on", default=commands.LOCAL,
        items=[(commands.LOCAL, "This machine", "prt on this machine"),
               (commands.MPI, "MPI hosts", "prt under mpirun over a hostfile (scripts/prt-mpirun)"),
               (commands.SLURM, "Slurm cluster", "sbatch of examples/slurm/render.sbatch"),
               (commands.JOINABLE, "Machines that join",
                "This machine's workers, and every machine that runs `prt join FILE`")])
    threads: bpy.props.IntProperty(
        name="Threads", default=0, min=0, max=1024,
        description="Rendering threads (of each worker of a parallel render); 0: every core")
    workers: bpy.props.IntProperty(
        name="Workers", default=0, min=0, max=4096,
        description="This machine: local workers (0: a serial render on the threads); MPI: "
                    "worker ranks (the master is one more)")
    strategy: bpy.props.EnumProperty(
        name="Strategy", items=_strategy_items(), default=commands.DEFAULT_STRATEGY,
        description="Load balancing of a parallel render (prt render --strategy)")
    verify: bpy.props.FloatProperty(
        name="Verify %", default=1.0, min=0.0, max=100.0,
        description="Spot checks of a parallel render: this percentage of each worker's pixels "
                    "rendered again elsewhere and compared bit for bit (prt render --verify)")
    serve: bpy.props.StringProperty(
        name="Serve", default="",
        description="Also serve the live page for a browser at [HOST:]PORT (prt render --serve; "
                    "empty: a free loopback port, for Blender only)")
    animation: bpy.props.EnumProperty(
        name="Animation", default='JOB',
        items=[('JOB', "One job", "The frame range as one balanced prt job (--frames), with the "
                "animation Blender's glTF exporter writes (object, camera and light transforms, "
                "shape-key weights)"),
               ('FRAMES', "Frame by frame", "Each frame exported and rendered on its own: "
                "whatever Blender animates (modifiers, materials) is seen")])
    hostfile: bpy.props.StringProperty(
        name="Hostfile", default="", subtype='FILE_PATH',
        description="Open MPI hostfile; its first host must be this machine (the master)")
    mpirun: bpy.props.StringProperty(
        name="Launcher", default="prt-mpirun",
        description="prt-mpirun (installed beside prt), or mpirun")
    sbatch_script: bpy.props.StringProperty(
        name="Job script", default="", subtype='FILE_PATH',
        description="examples/slurm/render.sbatch (installed as share/prt/slurm/render.sbatch); "
                    "empty: looked up beside prt")
    submit_folder: bpy.props.StringProperty(
        name="Submit folder", default="", subtype='DIR_PATH',
        description="A folder every node sees (the scene and the image go through it)")
    nodes: bpy.props.IntProperty(name="Nodes", default=2, min=1, max=65536)
    partition: bpy.props.StringProperty(name="Partition", default="",
                                        description="Empty: the cluster's default")
    accept_file: bpy.props.StringProperty(
        name="Invitation file", default="", subtype='FILE_PATH',
        description="prt render --accept-workers FILE: copy it to a machine and run `prt join "
                    "FILE` there to add it. Empty: in the render's temporary folder (its path "
                    "is shown in the info area)")


def register():
    bpy.utils.register_class(PRTRenderSettings)
    bpy.types.Scene.prt = bpy.props.PointerProperty(type=PRTRenderSettings)


def unregister():
    del bpy.types.Scene.prt
    bpy.utils.unregister_class(PRTRenderSettings)
