#!/usr/bin/env python3
"""Writes the ParaView view's settings from the families' schemas (`aokit settings --json`):

  vtkAOKitRenderView.h   the view class, with one Set<Family><Key>() per setting (ParaView calls a
                         property's command with the value alone, so each setting needs its own)
  AOKitView.xml          the view proxy: the method, R, and one property per setting with its
                         help, unit, range and default in the documentation and its domain

usage: generate_view.py SETTINGS.json HEADER.in HEADER.out XML.out
"""
import json
import sys
from xml.sax.saxutils import escape, quoteattr

FAMILIES = ["obscurance", "field", "hybrid"]  # AOMethod 1, 2, 3 (0: none)


def camel(text):
    return "".join(part[:1].upper() + part[1:] for part in text.replace("-", "_").split("_"))


def number(value):
    return repr(float(value)) if "." in str(value) or "e" in str(value) else str(value)


def default_value(s):
    d = s["default"]
    if s["kind"] == "flag":
        return "1" if d in ("1", "on", "true") else "0"
    if s["kind"] == "integer" and not d.lstrip("-").isdigit():
        return "0"  # the zero word ("auto") stands for 0
    return d


def cxx_setter(family, s):
    name = "Set" + camel(family) + camel(s["key"])
    arg = {"integer": "int", "flag": "int", "number": "double"}.get(s["kind"], "const char*")
    return (f"  // {s['help']}; {s['range_text']} (default {s['default_text']})\n"
            f"  void {name}({arg} v) {{ this->SetFamilySetting(\"{family}\", \"{s['key']}\", v); }}\n")


def xml_property(family, index, s):
    name = camel(family) + camel(s["key"])
    # ParaView's Python names a property by its label without spaces: "Obscurance Samples".
    label = family.capitalize() + " " + " ".join(w[:1].upper() + w[1:] for w in s["key"].split("_"))
    kind = s["kind"]
    tag = {"integer": "IntVectorProperty", "flag": "IntVectorProperty",
           "number": "DoubleVectorProperty"}.get(kind, "StringVectorProperty")
    default = default_value(s)
    lines = [f'      <{tag} name="{name}" label={quoteattr(label)} command="Set{name}" '
             f'number_of_elements="1" default_values={quoteattr(default)}>']
    if kind in ("integer", "number"):
        domain = "IntRangeDomain" if kind == "integer" else "DoubleRangeDomain"
        lo = 0 if s.get("zero_means") else s["lo"]
        lo = int(lo) if kind == "integer" else lo
        hi = int(s["hi"]) if kind == "integer" else s["hi"]
        lines.append(f'        <{domain} name="range" min="{lo}" max="{hi}"/>')
    elif kind == "flag":
        lines.append('        <BooleanDomain name="bool"/>')
    elif kind == "choice":
        lines.append('        <StringListDomain name="list">')
        lines += [f'          <String value={quoteattr(c)}/>' for c in s["choices"]]
        lines.append('        </StringListDomain>')
    lines.append(f"        <Documentation>{escape(s['help'])}; {escape(s['range_text'])} "
                 f"(default {escape(s['default_text'])}). aokit setting {family}:{s['key']}.</Documentation>")
    lines.append('        <Hints><PropertyWidgetDecorator type="GenericDecorator" mode="visibility" '
                 f'property="AOMethod" value="{index}"/></Hints>')
    lines.append(f"      </{tag}>")
    return "\n".join(lines)


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    settings_json, header_in, header_out, xml_out = sys.argv[1:]
    with open(settings_json) as f:
        methods = {m["name"]: m for m in json.load(f)}
    missing = [f for f in FAMILIES if f not in methods]
    if missing:
        sys.exit(f"generate_view.py: {settings_json} lacks the families {', '.join(missing)}")
    setters = "".join(cxx_setter(f, s) for f in FAMILIES for s in methods[f]["settings"])
    with open(header_in) as f:
        header = f.read().replace("@AOKIT_SETTING_METHODS@", setters)
    props = "\n".join(xml_property(f, i + 1, s) for i, f in enumerate(FAMILIES)
                      for s in methods[f]["settings"])
    enum = "\n".join(f'          <Entry value="{i + 1}" text="{f}"/>' for i, f in enumerate(FAMILIES))
    xml = f"""<ServerManagerConfiguration>
  <!-- Written by paraview/generate_view.py from the JSON of aokit settings: do not edit. -->
  <ProxyGroup name="views">
    <RenderViewProxy name="AOKitRenderView" class="vtkAOKitRenderView" label="AOKit Render View"
                     base_proxygroup="views" base_proxyname="RenderView">
      <Documentation>A render view with the aokit ambient occlusion of its method on every
        representation it shows.</Documentation>
      <IntVectorProperty name="AOMethod" label="AO Method" command="SetAOMethod"
                         number_of_elements="1" default_values="1">
        <EnumerationDomain name="enum">
          <Entry value="0" text="none"/>
{enum}
        </EnumerationDomain>
        <Documentation>The AO family: none, obscurance (screen space), field (precomputed
          occluder fields), hybrid (voxels and rays).</Documentation>
      </IntVectorProperty>
      <DoubleVectorProperty name="AORadius" label="AO Radius" command="SetAORadius"
                            number_of_elements="1" default_values="0">
        <DoubleRangeDomain name="range" min="0"/>
        <Documentation>AO radius R in world units where the method's own radius setting is 0;
          0 (default): a tenth of the diagonal of the bounds of all visible data (every rank's).</Documentation>
      </DoubleVectorProperty>
      <StringVectorProperty name="AOOutputFile" label="AO Output File" command="SetAOOutputFile"
                            number_of_elements="1" default_values="" panel_visibility="advanced">
        <FileListDomain name="files"/>
        <Documentation>When set, each still render writes its AO to this file as the CLI's
          --ao-float does (float32, bottom row first, -1 where no surface).</Documentation>
      </StringVectorProperty>
      <DoubleVectorProperty name="AOExchangedBytes" command="GetAOExchangedBytes" information_only="1"
                            number_of_elements="1" default_values="0" panel_visibility="never">
        <SimpleDoubleInformationHelper/>
        <Documentation>Bytes this process sent to the other ranks in the last frame (G-buffer
          composite, gathered meshes); 0 in one process.</Documentation>
      </DoubleVectorProperty>
{props}
    </RenderViewProxy>
  </ProxyGroup>
</ServerManagerConfiguration>
"""
    for path, text in ((header_out, header), (xml_out, xml)):
        with open(path + ".tmp", "w") as f:
            f.write(text)
    import os
    for path in (header_out, xml_out):
        os.replace(path + ".tmp", path)


if __name__ == "__main__":
    main()
