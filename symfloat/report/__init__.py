"""Writers of the verification record, the errata report and the notebooks."""
