"""Fields, not wells: many cards through the single-card analyses into one results store.

A manifest (:mod:`pumpjack_cli.readers.manifest`) names a well, a unit and a card per
row. Each card goes through the very analyses of `pumpjack torque` and `pumpjack
downhole`, so a stored summary is the single command's ``-f json`` summary; a card or a
unit that cannot be analysed becomes an ``error`` row with the message the single
command would print. Results go to the SQLite store of :mod:`pumpjack_cli.readers.store`.

* :mod:`.per_card`: the options of a run and the analyses of a task's cards, a unit's cards
  together (:func:`.per_card.analyse_chunk`, the function every executor runs);
* :mod:`.keys`: the content keys that tell a card already done (:func:`.keys.options_key`,
  :func:`.keys.unit_digest`);
* :mod:`.executors`: a local process pool and a Dask cluster;
* :mod:`.run`: :func:`.run.run_batch`, the manifest through an executor into the store.
"""
