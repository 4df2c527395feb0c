"""The run layer: a validated unit plus the command's options in, core calls out, a result table back.

One module per analysis (:mod:`.kinematics`, :mod:`.reactions`, :mod:`.dynamics`,
:mod:`.inertia`, :mod:`.listing`); the core inputs every analysis shares (crank speed,
card runs, the machine, the well load, the masses) are decided once in :mod:`.inputs`.
Each analysis returns a :class:`~pumpjack_cli.results.Result`; commands choose the
columns shown by default and hand it to the renderer. Nothing here prints.
"""
