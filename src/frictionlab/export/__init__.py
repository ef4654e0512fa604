"""The law outside frictionlab: a portable C core and user routines for FE codes.

* ``subloading.h`` / ``subloading.c``: the law's update of one contact point in C99,
  bit-identical to :mod:`frictionlab.subloading.kernels`;
* ``uinter.c``: Abaqus/Standard UINTER and Abaqus/Explicit VUINTER calling it;
* :mod:`frictionlab.export.c_core`: build with the system's compiler, ctypes binding;
* :mod:`frictionlab.export.abaqus`: the files of ``frictionlab export abaqus``.
"""
