"""PRT's panels in the Render properties, shown while PRT is the render engine."""
import bpy

from . import commands


class PRTPanel:
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    bl_context = "render"
    COMPAT_ENGINES = {'PRT'}

    @classmethod
    def poll(cls, context):
        return context.engine in cls.COMPAT_ENGINES


class RENDER_PT_prt_sampling(PRTPanel, bpy.types.Panel):
    bl_label = "PRT"

    def draw(self, context):
        s = context.scene.prt
        layout = self.layout
        layout.use_property_split = True
        layout.prop(s, "integrator")
        layout.prop(s, "samples")
        layout.prop(s, "animation")
        layout.prop(s, "prt_path")


class RENDER_PT_prt_where(PRTPanel, bpy.types.Panel):
    bl_label = "Where to render"
    bl_parent_id = "RENDER_PT_prt_sampling"

    def draw(self, context):
        s = context.scene.prt
        layout = self.layout
        layout.use_property_split = True
        layout.prop(s, "where")
        layout.prop(s, "threads")
        if s.where in (commands.LOCAL, commands.MPI, commands.JOINABLE):
            layout.prop(s, "workers")
        if s.where == commands.MPI:
            layout.prop(s, "hostfile")
            layout.prop(s, "mpirun")
        elif s.where == commands.SLURM:
            layout.prop(s, "submit_folder")
            layout.prop(s, "nodes")
            layout.prop(s, "partition")
            layout.prop(s, "sbatch_script")
        elif s.where == commands.JOINABLE:
            layout.prop(s, "accept_file")
            layout.label(text="Add a machine: prt join FILE there", icon='INFO')
        parallel = s.where != commands.LOCAL or s.workers > 0
        column = layout.column()
        column.active = parallel
        column.prop(s, "strategy")
        column.prop(s, "verify")
        if s.where != commands.SLURM:
            layout.prop(s, "serve")


classes = (RENDER_PT_prt_sampling, RENDER_PT_prt_where)


def _compatible_panels():
    """Blender's own panels that apply to any engine (dimensions, output, colour management)."""
    for name in ("RENDER_PT_color_management", "RENDER_PT_color_management_curves",
                 "RENDER_PT_format", "RENDER_PT_frame_range", "RENDER_PT_time_stretching",
                 "RENDER_PT_output", "RENDER_PT_encoding", "RENDER_PT_encoding_video",
                 "RENDER_PT_encoding_audio", "RENDER_PT_stamp", "RENDER_PT_post_processing",
                 "RENDER_PT_output_views", "RENDER_PT_format_presets", "DATA_PT_lens",
                 "DATA_PT_camera", "DATA_PT_camera_display", "DATA_PT_light", "DATA_PT_context_light",
                 "DATA_PT_EEVEE_light", "DATA_PT_context_camera", "EEVEE_MATERIAL_PT_surface",
                 "EEVEE_MATERIAL_PT_context_material"):
        panel = getattr(bpy.types, name, None)
        if panel is not None and hasattr(panel, "COMPAT_ENGINES"):
            yield panel


def register():
    for c in classes:
        bpy.utils.register_class(c)
    for panel in _compatible_panels():
        panel.COMPAT_ENGINES.add('PRT')


def unregister():
    for panel in _compatible_panels():
        panel.COMPAT_ENGINES.discard('PRT')
    for c in reversed(classes):
        bpy.utils.unregister_class(c)
