"""wear: the wear law integrated over the moving contact patch, the worn and dented surface, the pipeline."""
