"""hullopt: hull-form optimisation of high-speed vessels for seakeeping in head seas.

One import names the public objects:

    DesignVariables, generate_hull, load_hull      parametric or read hulls
    hydrostatics, mass_properties                  displacement, coefficients, GM; mass properties
    compute_raos, evaluation_frequencies           heave and pitch RAOs (time-domain strip method or STF)
    forced_oscillation                             a forced heave or pitch test on the instantaneous hull
    calm_water                                     the steady force and running sinkage and trim in calm water
    evaluate                                       rms vertical accelerations and MSI in head seas
    design, Design                                 a design from Python values (speed_kn= or speed_m_s=), built
                                                   as the commands build a config's
    load_design                                    a design config as `hullopt evaluate` reads it
    run                                            any hullopt command in-process (campaigns)
    InputError                                     bad input; the message is the CLI's

SI units everywhere; axes and phases as in docs/conventions.md.
"""
from ._hullopt import (  # noqa: F401
    Design,
    DesignVariables,
    Hull,
    InputError,
    MassProperties,
    __version__,
    compute_raos,
    design,
    evaluate,
    evaluation_frequencies,
    forced_oscillation,
    calm_water,
    generate_hull,
    hydrostatics,
    load_design,
    load_hull,
    mass_properties,
    run,
)
