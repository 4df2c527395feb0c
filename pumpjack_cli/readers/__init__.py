"""File readers, in one place: unit files, dynamometer cards, batch manifests, the results store.

A reader turns a file into plain data (SI numbers, text, line numbers for messages) and
refuses a bad file with one line naming the file, the line and the field; it does no
physics. This layer sits beside :mod:`pumpjack_cli.config`: it imports only
:mod:`pumpjack_cli.errors`, :mod:`pumpjack_cli.quantities` and
:mod:`pumpjack_cli.text_input` (and numpy where arrays are read).
"""
