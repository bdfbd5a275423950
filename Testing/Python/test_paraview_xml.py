#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""ParaView's server-manager XML (ParaView/Plugin/VTKBloom.xml) against the C++ classes it
configures: every property's default is the C++ default, every enumeration's entry is the value
of the C++ setter of that name, and the preset list is vtkBloomParameters::GetPresetNames().
The XML states them by hand; this test is what keeps them one fact. It needs no ParaView: the
plugin's classes are read through the vtkbloom package (the plugin's vtkPV* subclasses add no
parameters of their own)."""

import math
import re
import os
import sys
import unittest
import xml.etree.ElementTree as ElementTree

import vtkbloom

XML = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "ParaView", "Plugin",
                   "VTKBloom.xml")
# The plugin's subclasses, and the vtkbloom class whose defaults they keep.
SUBCLASSES = {"vtkPVBloomParameters": "vtkBloomParameters", "vtkPVImageBloom": "vtkImageBloom"}


def proxies():
    """(proxy name, vtkbloom class, XML element) of every proxy whose class vtkbloom has."""
    for proxy in ElementTree.parse(XML).iter():
        if proxy.tag in ("Proxy", "SourceProxy") and proxy.get("class"):
            name = SUBCLASSES.get(proxy.get("class"), proxy.get("class"))
            if hasattr(vtkbloom, name):
                yield proxy.get("name"), getattr(vtkbloom, name), proxy


def properties(proxy):
    for prop in proxy:
        command = prop.get("command") or ""
        if prop.tag.endswith("VectorProperty") and command.startswith("Set") and \
                prop.get("information_only") != "1":
            yield prop, command


def same(xml_value, value):
    if isinstance(value, str):
        return xml_value == value
    if isinstance(value, bool):
        value = int(value)
    expected = float(xml_value)
    return math.isclose(expected, float(value), rel_tol=1e-7, abs_tol=0.0)


class ParaViewXML(unittest.TestCase):
    def test_defaults_are_the_classes_defaults(self):
        compared, wrong = 0, []
        for name, cls, proxy in proxies():
            obj = cls()
            for prop, command in properties(proxy):
                defaults = prop.get("default_values")
                getter = getattr(obj, "G" + command[1:], None)
                if not defaults or getter is None:
                    continue
                try:
                    value = getter()
                except TypeError:  # a getter with arguments: not a plain property
                    continue
                values = value if isinstance(value, tuple) else (value,)
                xml_values = defaults.split() if prop.tag != "StringVectorProperty" else [defaults]
                if prop.get("name") == "Preset" and defaults == "custom":
                    continue  # "custom": no preset applied, the parameters' own defaults
                compared += 1
                if len(xml_values) != len(values) or not all(map(same, xml_values, values)):
                    wrong.append("%s.%s: XML %s, C++ %s" % (name, prop.get("name"), defaults, value))
        self.assertEqual(wrong, [])
        self.assertGreaterEqual(compared, 50, "the XML's properties were not found")

    def test_enumerations_are_the_classes_constants(self):
        # An entry's text names the C++ constant ("Excess knee" is EXCESS_KNEE, "PSF" is
        # BLOOM_PSF, "Jimenez 13-tap" is JIMENEZ13), and its value is that constant's.
        def key(text):  # a parenthesis of words is a comment: "Reflect (conserves energy)"
            return re.sub(r"[^A-Z0-9]", "", re.sub(r"\([^)]*[a-z][^)]*\)", "", text).upper())

        checked, wrong = 0, []
        for name, cls, proxy in proxies():
            # The kernels' constants are the filters' that use them.
            places = (cls, vtkbloom.vtkBloomParameters, vtkbloom.vtkImageBloomThreshold,
                      vtkbloom.vtkImagePyramidDown, vtkbloom.vtkImagePyramidUp,
                      vtkbloom.vtkImageSeparableGaussian)
            constants = {}
            for place in places:
                for attribute in dir(place):
                    value = getattr(place, attribute)
                    if attribute.isupper() and isinstance(value, int):
                        short = re.sub(r"^(BLOOM|BLUR|CONVOLUTION|PSF|COMPRESSION|PIXEL_TYPE)_", "", attribute)
                        constants.setdefault(key(short), value)
            for prop, command in properties(proxy):
                domain = prop.find("EnumerationDomain")
                for entry in domain.findall("Entry") if domain is not None else ():
                    text, value = entry.get("text"), int(entry.get("value"))
                    checked += 1
                    if prop.get("name") == "PSFTailScale":  # the value is the scale itself
                        scale = re.search(r"1/(\d+)", text)
                        if value != (int(scale.group(1)) if scale else 1 if text == "Exact" else -1):
                            wrong.append("PSFTailScale: entry '%s' is %d" % (text, value))
                        continue
                    k = key(text)
                    found = constants.get(k)
                    if found is None:
                        found = next((v for c, v in constants.items() if c and k.startswith(c)), None)
                    if found != value:
                        wrong.append("%s.%s: entry '%s' is %d in the XML, %s in C++"
                                     % (name, prop.get("name"), text, value, found))
        self.assertEqual(wrong, [])
        self.assertGreaterEqual(checked, 60)

    def test_the_preset_lists_are_get_preset_names(self):
        names = list(vtkbloom.vtkBloomParameters.GetPresetNames())
        lists = 0
        for domain in ElementTree.parse(XML).iter("StringListDomain"):
            entries = [s.get("value") for s in domain.findall("String")]
            if names[0] in entries:
                self.assertEqual([e for e in entries if e != "custom"], names)
                lists += 1
        self.assertGreaterEqual(lists, 2)

if __name__ == "__main__":
    from unittest_main import main

    sys.exit(main())
