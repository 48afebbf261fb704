"""rc2000tlm from Python: the RC2000 board model's runs, sweeps and studies as typed results.

    import rc2000tlm
    r = rc2000tlm.run(lanes=2, steps=20)            # one board run -> RunResult
    r.to_dataframe()                                # per step: convergence, simulated time
    r.banks_dataframe()                             # per bank: bytes, busy time, bandwidth
    s = rc2000tlm.sweep(lanes=[1, 2], bits=[15], steps=20,
                        scenes=[{"paper": {"faces": 70, "patches": 280}}])
    s.to_dataframe()                                # one row per configuration (and scene)
    rc2000tlm.study("configs/studies/default.toml") # a study file (docs/studies.md)
    rc2000tlm.paper().to_dataframe()                # Table 2 as `rc2000sim paper` predicts it
    d = rc2000tlm.design(device="virtex4-sx55", lanes="1-4", steps=30)  # `rc2000sim design`
    d.best, d.front, d.to_dataframe()               # the fastest design, the Pareto front, every design
    rc2000tlm.load("out/sweep")                     # outputs rc2000sim already wrote (design too)

SystemC elaborates once per process, so every simulation runs in a worker process of a pool sized as
`rc2000sim --jobs` (jobs=; rc2000tlm.workers); errors come back as ValueError or RuntimeError with the
command line's message. README, "Use it from Python".
"""
from .results import DesignBound, DesignPoint, DesignResult, OutputError, PaperResult, RunResult, SweepResult, load
from .workers import design, design_defaults, paper, run, run_many, run_options, study, sweep, sweep_options

__all__ = ["DesignBound", "DesignPoint", "DesignResult", "OutputError", "PaperResult", "RunResult", "SweepResult", "design",
           "design_defaults", "load", "paper", "run", "run_many", "run_options", "study", "sweep", "sweep_options"]
