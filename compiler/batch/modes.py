"""Where a Dask build's files go (`--results`): a module of its own so the command line can offer
the choice without importing the builder."""

RESULT_MODES = ("return", "shared")  # files come back to be written here / workers write into -o
