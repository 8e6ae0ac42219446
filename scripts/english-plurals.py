#!/usr/bin/env python3
"""Fills resources/i18n/sortie_en.ts (made by `lupdate -pluralonly`): the English source words say
"%n waypoint(s)"; English has two forms, "1 waypoint" and "2 waypoints", which only a translation
gives (Qt picks the form by %n). A "(s)" is dropped for one and becomes "s" for many; the few
sentences that change more are spelled out below. Usage: english-plurals.py FILE.ts"""
import re
import sys
import xml.etree.ElementTree as ET

# Sources whose singular is more than the "(s)" dropped.
SINGULAR = {
    "%n batteries": "%n battery",
    "%n AMSL altitude(s), the first at %1, were not checked against the route's limits: the take-off elevation is unknown.":
        "%n AMSL altitude, at %1, was not checked against the route's limits: the take-off elevation is unknown.",
    "%n geotagged copies, geo.txt and geotags.csv written to %1.": "%n geotagged copy, geo.txt and geotags.csv written to %1.",
    "%1 of %n photos placed on %2's track (camera clock %3 s).": "%1 of %n photo placed on %2's track (camera clock %3 s).",
    "%1 of %n photos placed where %2 took them, paired with its photo events (camera clock %3 s off).":
        "%1 of %n photo placed where %2 took it, paired with its photo events (camera clock %3 s off).",
    "%n photo(s) the vehicle took are not in the folder.": "%n photo the vehicle took is not in the folder.",
}


def forms(source):
    singular = SINGULAR.get(source, source.replace("(s)", ""))
    plural = source.replace("(s)", "s")
    return singular, plural


path = sys.argv[1]
tree = ET.parse(path)
for message in tree.getroot().iter("message"):
    if message.get("numerus") != "yes":
        continue
    translation = message.find("translation")
    for form in list(translation):
        translation.remove(form)
    for text in forms(message.findtext("source")):
        ET.SubElement(translation, "numerusform").text = text
    translation.attrib.pop("type", None)
tree.write(path, encoding="utf-8", xml_declaration=True)
