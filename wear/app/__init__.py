"""The toolkit's front door (case files, outputs, figures, command line), kept apart from the physics."""
