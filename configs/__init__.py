"""Bundled unit files (TOML), installed as package data; see `pumpjack units`."""
