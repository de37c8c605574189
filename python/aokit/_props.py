"""Marks on props that every family reads (unmarked: casts, receives, dynamic)."""
from . import aokitVTK as _vtk

_P = _vtk.vtkAOKitProps


def set_casts_ao(prop, on=True):
    """Whether the prop occludes others (voxelized, baked, in the reference)."""
    _P.SetCastsAO(prop, bool(on))


def set_receives_ao(prop, on=True):
    """Whether the prop's pixels are darkened by AO."""
    _P.SetReceivesAO(prop, bool(on))


def set_static(prop, on=True):
    """A static prop never moves or deforms: a family may bake its AO once."""
    _P.SetStatic(prop, bool(on))


def casts_ao(prop):
    return _P.GetCastsAO(prop)


def receives_ao(prop):
    return _P.GetReceivesAO(prop)


def is_static(prop):
    return _P.GetStatic(prop)
