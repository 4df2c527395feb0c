"""The sucker-rod string: its sections and the damped wave equation along it.

``string`` (RodString), ``tables`` (API rods, sinker bars, grades, building a string),
``gibbs`` and ``everitt_jennings`` (the two marches), ``downhole`` (pump card, forward
transfer, checks, method registry), ``analysis`` (pump-card figures, work, rod loading).
"""
