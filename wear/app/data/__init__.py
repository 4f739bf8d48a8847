"""Data installed with the toolkit: the sample of ``impactwear calibrate`` (``calibration_sample.csv``), the
Kharaz et al. (2001) measurements (``kharaz2001.csv``) and the outputs of a real OpenFOAM v1912 run of sand through a
pipe bend (:data:`OPENFOAM_BEND`; its case dictionaries and the script that regenerates it are in
``examples/openfoam_bend``)."""

from pathlib import Path

__all__ = ["OPENFOAM_BEND"]

#: The OpenFOAM bend run's outputs: ``polyMesh/`` (the mesh), ``patchPostProcessing1/<t>/<patch>.post.gz`` (every
#: parcel–wall hit), ``kinematicCloudQ.gz`` (OpenFOAM's Finnie eroded volume per wall face), ``versions.txt``,
#: ``cloud_summary.txt``.
OPENFOAM_BEND = Path(__file__).resolve().parent / "openfoam_bend"
