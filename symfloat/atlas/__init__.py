"""The stability atlas of the floating box: for every shape (b/a, c/a) the stable positions along
the density, computed cell by cell on Dask (optional extra ``atlas``: dask[distributed], pyarrow)."""
