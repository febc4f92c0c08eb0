"""Plain OpenSeesPy scripts run by both BeamSolid and OpenSeesPy.

Each module exposes ``run(ops) -> dict`` and uses nothing but the ``ops``
commands it is given, so the same code runs with
``import openseespy.opensees as ops`` and ``import beamsolid.opensees as ops``.
Recorder files are written to the current directory (the runner gives each
script its own).
"""

SCRIPTS = (
    "cantilever3d",
    "brick_block",
    "truss_plastic",
    "zerolength_orient",
    "recorders_text",
    "element_responses",
    "command_behaviour",
    "staged_constraints",
    "mixed_pile",
    "response_names",
    "zerolength_contact",
    "beam_contact",
    "frames_2d",
    "analysis_idioms",
    "quad_mesh",
    "corotational_2d",
    "constraints_and_queries",
    "spring_chain_1d",
    "nonlinear_truss_2d",
    "moment_curvature",
    "rc_frame_2d",
    "steel_frame_wf",
    "aggregator_2d",
    "public_examples_static",
    "time_series",
    "ground_motion",
    "dynamics_sdof_mdof",
    "shear_column",
    "newton_variants",
    "modal_properties",
    "quasi_newton",
    "block_meshes",
    "system_prints",
    "damping_regions",
    "modal_damping",
    "explicit_difference",
    "earthquake_2d",
    "example3_cantilever",
    "force_beam_iterations",
    "response_spectrum",
    "script_queries",
    "solid_elements",
    "solid_footing",
    "bilin_frame_2d",
)
