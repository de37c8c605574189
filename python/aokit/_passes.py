"""The passes: the wrapped vtkAOKit*Pass classes with one Set<Key>/Get<Key> pair per setting,
made from the family's settings table at import (so docstrings, ranges and defaults are the kit's)."""
from . import aokitVTK as _vtk


def _text(value):
    """A Python value as the kit's setting text."""
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def _value(kind, text):
    """A setting's text as a Python value of its kind (a word such as 'auto' stays text)."""
    try:
        if kind == "integer":
            return int(text)
        if kind == "number":
            return float(text)
        if kind == "flag":
            return text == "1"
    except ValueError:
        pass
    return text


class _Settings:
    """Settings by key for any aokit pass: set(key, value), get(key), settings()."""

    def __init__(self, **settings):
        for key, value in settings.items():
            self.set(key, value)

    def set(self, key, value):
        if not self.SetSetting(str(key), _text(value)):
            raise ValueError(self.GetLastError())

    def get(self, key):
        text = self.GetSetting(str(key))
        if self.GetLastError():
            raise ValueError(self.GetLastError())
        return _value(self._kinds[key], text)

    def settings(self):
        """Every setting's current value, by key."""
        return {key: self.get(key) for key in self._kinds}

    def set_scene_radius(self, radius):
        self.SetSceneRadius(radius)

    # The wrapped methods that report a bad value by returning False raise instead.
    def SetSceneRadius(self, radius):
        if not _vtk.vtkAOKitPass.SetSceneRadius(self, float(radius)):
            raise ValueError(self.GetLastError())

    def SetSceneFalloff(self, name):
        if not _vtk.vtkAOKitPass.SetSceneFalloff(self, str(name)):
            raise ValueError(self.GetLastError())


def _accessors(key, doc):
    def setter(self, value):
        self.set(key, value)

    def getter(self):
        return self.get(key)

    setter.__doc__ = doc
    getter.__doc__ = doc
    return setter, getter


def _family(name, wrapped):
    proto = wrapped()
    kinds, members = {}, {}
    lines = []
    for i in range(proto.GetNumberOfSettings()):
        key, kind = proto.GetSettingKey(i), proto.GetSettingKind(i)
        doc = "%s: %s; %s (default %s)" % (key, proto.GetSettingHelp(i), proto.GetSettingRange(i),
                                          proto.GetSettingDefault(i))
        lines.append("    " + doc)
        kinds[key] = kind
        cap = key[0].upper() + key[1:]
        members["Set" + cap], members["Get" + cap] = _accessors(key, doc)
    members["_kinds"] = kinds
    members["__doc__"] = (wrapped.__doc__ or "") + "\n\nSettings (Set<Key>/Get<Key>, or by keyword):\n" + "\n".join(lines)
    members["__module__"] = __name__.rsplit(".", 1)[0]
    return type(name, (_Settings, wrapped), members)


ObscurancePass = _family("ObscurancePass", _vtk.vtkAOKitObscurancePass)
HybridPass = _family("HybridPass", _vtk.vtkAOKitHybridPass)
FieldPass = _family("FieldPass", _vtk.vtkAOKitFieldPass)

_BY_METHOD = {"obscurance": ObscurancePass, "hybrid": HybridPass, "field": FieldPass}


def methods():
    """The AO families a pass can be made of."""
    return list(_BY_METHOD)


def new_pass(method, **settings):
    """A pass of the named family ('obscurance', 'hybrid', 'field') with its settings."""
    if method not in _BY_METHOD:
        raise ValueError("unknown AO method '%s' (known: %s)" % (method, ", ".join(_BY_METHOD)))
    return _BY_METHOD[method](**settings)
