#!/usr/bin/python3
"""Checks of a web map page as Chromium drew it (tests/browser/web_map_plan.sh).

    check_web_map.py click PAGE RECORD   prints LON,LAT inside RECORD's no-go feature
    check_web_map.py pick PAGE CLASS     prints the record of CLASS's largest no-go
                                         feature and LON,LAT inside it
    check_web_map.py check FOLDER RECORD checks a `plan --html` page: FOLDER's
                                         dom.html against the library's files there
    check_web_map.py check-chart FOLDER RECORD
                                         the same for a `render chart --html` page
    check_web_map.py pick-obstacle PAGE  prints the first obstacle's id and LON,LAT inside it
    check_web_map.py check-mission FOLDER ID
                                         the same for `mission plan|simulate --html` pages
Exit 1 naming what differs.
"""

import collections
import html
import json
import re
import sys


def positions(q):
    out, x, y = [], 0, 0
    for i in range(0, len(q), 2):
        x, y = x + q[i], y + q[i + 1]
        out.append([x / 1e7, y / 1e7])
    return out


def page_data(path):
    """The page's layers, their lines and rings decoded from steps of 1e-7 degrees as the page decodes them."""
    text = open(path, encoding="utf-8").read()
    found = re.search(r'<script id="dg-data" type="application/json">(.*?)</script>', text, re.S)
    data = json.loads(found.group(1).replace("<\\/", "</"))
    for l in data["layers"]:
        for f in l["features"]:
            g = f["geometry"]
            if "q" in g:
                q = g.pop("q")
                g["coordinates"] = (positions(q) if g["type"] == "LineString" else
                                    [positions(r) for r in q] if g["type"] == "Polygon" else
                                    [[positions(r) for r in p] for p in q])
    return data, text


def layer(data, key):
    return next(l for l in data["layers"] if l["id"] == key)


def polygons(geometry):
    return [geometry["coordinates"]] if geometry["type"] == "Polygon" else geometry["coordinates"]


def inside(rings, x, y):
    odd = False
    for ring in rings:
        for (xi, yi), (xj, yj) in zip(ring, ring[1:] + ring[:1]):
            if (yi > y) != (yj > y) and x < (xj - xi) * (y - yi) / (yj - yi) + xi:
                odd = not odd
    return odd


def point_inside(feature):
    """A point well inside the feature: the grid point of its largest polygon
    farthest from every edge, on a 60 x 60 grid over its box."""
    rings = max(polygons(feature["geometry"]), key=lambda r: len(r[0]))
    xs = [p[0] for p in rings[0]]
    ys = [p[1] for p in rings[0]]
    best, best_d = None, -1.0
    for i in range(1, 60):
        for j in range(1, 60):
            x = min(xs) + (max(xs) - min(xs)) * i / 60
            y = min(ys) + (max(ys) - min(ys)) * j / 60
            if not inside(rings, x, y):
                continue
            d = min(abs(x - p[0]) + abs(y - p[1]) for ring in rings for p in ring)
            if d > best_d:
                best, best_d = (x, y), d
    if best is None:
        raise SystemExit(f"no point inside {feature['properties']['record']} on the grid")
    return best


def fail(what):
    print("web map check: " + what)
    sys.exit(1)


def drawn_page(folder):
    data, _ = page_data(f"{folder}/page.html")
    dom = open(f"{folder}/dom.html", encoding="utf-8").read()
    found = re.search(r'<pre id="dg-test">(.*?)</pre>', dom, re.S)
    if not found:
        fail("the page wrote no test output (did Leaflet load with the network off?)")
    drawn = json.loads(html.unescape(found.group(1)))
    # Every layer drawn with every feature.
    for l in data["layers"]:
        if drawn["layers"][l["id"]] != len(l["features"]):
            fail(f"layer {l['id']}: {drawn['layers'][l['id']]} drawn of {len(l['features'])}")
    return data, dom, drawn


def chart_info(folder):
    info = json.load(open(f"{folder}/info.json"))
    return info[0] if isinstance(info, list) else info


def check_no_go_by_class(data, info):
    """The library's own count: chart info's no-go by class (the cells' coverage apart)."""
    by_class = collections.Counter(f["properties"]["class"] for f in layer(data, "no_go")["features"])
    by_class.pop("M_COVR", 0)
    if dict(by_class) != info["no_go"]["no_go_by_class"]:
        fail(f"no-go by class {dict(by_class)}, chart info says {info['no_go']['no_go_by_class']}")


def check_popup_and_shots(folder, dom, record):
    """The click: a popup naming the record and its DRVAL1 as GDAL reads it from the cell; two zooms, two pictures."""
    drval1 = re.search(r"DRVAL1 \(Real\) = ([0-9.]+)", open(f"{folder}/ogrinfo.txt").read())
    if not drval1:
        fail(f"ogrinfo gave no DRVAL1 for {record}")
    popup = re.search(r'class="leaflet-popup-content"[^>]*>(.*?)</div></div>', dom, re.S)
    if not popup:
        fail("the click opened no popup")
    text = html.unescape(re.sub(r"<[^>]+>", " ", popup.group(1)))
    if record not in text or f"DRVAL1 {float(drval1.group(1)):g} m" not in text:
        fail(f"the popup does not name {record} with DRVAL1 {drval1.group(1)} m: {text[:300]}")
    shots = [open(f"{folder}/zoom{z}.png", "rb").read() for z in ("_far", "_near")]
    if any(len(s) < 20000 or s[:8] != b"\x89PNG\r\n\x1a\n" for s in shots) or shots[0] == shots[1]:
        fail("the screenshots at two zoom levels are missing, tiny or the same")
    return drval1.group(1)


def check(folder, record):
    data, dom, drawn = drawn_page(folder)
    plan = json.load(open(f"{folder}/plan.json"))
    check_no_go_by_class(data, chart_info(folder))
    if drawn["layers"]["obstacles"] != plan["obstacles"]:
        fail(f"obstacles: {drawn['layers']['obstacles']} drawn, plan says {plan['obstacles']}")
    if drawn["layers"]["waypoints"] != plan["waypoints"] or drawn["layers"]["route"] != plan["waypoints"] - 1:
        fail(f"waypoints {drawn['layers']['waypoints']}, legs {drawn['layers']['route']}; plan: {plan['waypoints']}")
    # The waypoint table is the route file's line, to 1e-7 degrees.
    route = json.load(open(f"{folder}/route.geojson"))
    line = next(f for f in route["features"] if f["geometry"]["type"] == "LineString")["geometry"]["coordinates"]
    table = drawn["table"]
    if len(table) != len(line):
        fail(f"table has {len(table)} rows, the route {len(line)} waypoints")
    for row, (lon, lat, *_) in zip(table, line):
        if abs(row[1] - lon) > 1e-7 or abs(row[2] - lat) > 1e-7:
            fail(f"table row {row[0]}: {row[1]}, {row[2]}; the route file: {lon}, {lat}")
    drval1 = check_popup_and_shots(folder, dom, record)
    print(f"web map: {sum(drawn['layers'].values())} features in {len(drawn['layers'])} layers drawn as the library "
          f"counts them; {record} explained (DRVAL1 {drval1} m); {len(table)} waypoints equal the route file")


def check_chart(folder, record):
    data, dom, drawn = drawn_page(folder)
    info = chart_info(folder)
    check_no_go_by_class(data, info)
    cells = sorted(c["name"] for c in info["cells"])
    if sorted(row[0] for row in drawn["table"]) != cells:
        fail(f"the cells' table {[row[0] for row in drawn['table']]}, chart info lists {cells}")
    if sorted({f["properties"]["cell"] for f in layer(data, "cells")["features"]}) != cells:
        fail("the cells layer does not outline every cell chart info lists")
    land = sum(1 for f in layer(data, "no_go")["features"] if f["properties"]["class"] == "LNDARE")
    if drawn["layers"]["land"] != land or land != info["no_go"]["no_go_by_class"].get("LNDARE", 0):
        fail(f"land: {drawn['layers']['land']} drawn, {land} LNDARE no-go features")
    drval1 = check_popup_and_shots(folder, dom, record)
    print(f"web map: {sum(drawn['layers'].values())} features in {len(drawn['layers'])} layers drawn as the library "
          f"counts them; {len(cells)} cells; {record} explained (DRVAL1 {drval1} m)")


def check_mission(folder, obstacle):
    data, dom, drawn = drawn_page(folder)
    plan = json.load(open(f"{folder}/plan.json"))
    if drawn["layers"]["conflicts"] != len(plan["resolutions"]):
        fail(f"conflicts: {drawn['layers']['conflicts']} drawn, mission plan says {len(plan['resolutions'])}")
    # The waypoints and the table are what mission export writes, to 1e-7 degrees.
    export = json.load(open(f"{folder}/export.geojson"))
    points = [f for f in export["features"] if f["geometry"]["type"] == "Point"]
    if drawn["layers"]["waypoints"] != len(points) or len(drawn["table"]) != len(points):
        fail(f"waypoints {drawn['layers']['waypoints']}, table {len(drawn['table'])}; mission export: {len(points)}")
    for row, p in zip(drawn["table"], points):
        lon, lat = p["geometry"]["coordinates"][:2]
        if abs(row[1] - lon) > 1e-7 or abs(row[2] - lat) > 1e-7:
            fail(f"waypoint {row[0]}: {row[1]}, {row[2]}; mission export: {lon}, {lat}")
    # The mission's raster chart: its depth shading decoded by the browser, as big as the page says.
    pictures = drawn.get("images", {})
    if len(pictures) != 1 or any(not p or p["width"] < 100 or p["height"] < 100 for p in pictures.values()):
        fail(f"the mission's raster chart is not drawn as a picture: {pictures}")
    if drawn["layers"]["legs"] != len(points) - 1:
        fail(f"legs {drawn['layers']['legs']} for {len(points)} waypoints")
    popup = re.search(r'class="leaflet-popup-content"[^>]*>(.*?)</div></div>', dom, re.S)
    if not popup or obstacle not in html.unescape(re.sub(r"<[^>]+>", " ", popup.group(1))):
        fail(f"a click inside obstacle {obstacle} opened no popup naming it")
    shots = [open(f"{folder}/zoom{z}.png", "rb").read() for z in ("_far", "_near")]
    if any(len(s) < 20000 or s[:8] != b"\x89PNG\r\n\x1a\n" for s in shots) or shots[0] == shots[1]:
        fail("the screenshots at two zoom levels are missing, tiny or the same")
    # The simulated page: the track, and the objects the sonar found.
    simulated = open(f"{folder}/simulated_dom.html", encoding="utf-8").read()
    found = re.search(r'<pre id="dg-test">(.*?)</pre>', simulated, re.S)
    if not found:
        fail("the simulated page wrote no test output")
    layers = json.loads(html.unescape(found.group(1)))["layers"]
    run = json.load(open(f"{folder}/run.json"))
    if layers.get("track", 0) < 1 or "detected" not in layers:
        fail(f"the simulated page has no track or no found objects: {layers}")
    # The checked page: the plan as written, mission check's obstacles and conflicts.
    checked = json.loads(html.unescape(re.search(r'<pre id="dg-test">(.*?)</pre>',
                                                 open(f"{folder}/check_dom.html", encoding="utf-8").read(),
                                                 re.S).group(1)))
    check_report = json.load(open(f"{folder}/check.json"))
    written = [f for f in json.load(open(f"{folder}/export_written.geojson"))["features"]
               if f["geometry"]["type"] == "Point"]
    if (checked["layers"]["waypoints"] != len(written) or checked["layers"]["conflicts"] != len(check_report["conflicts"])
            or checked["layers"]["obstacles"] != check_report["obstacles"]):
        fail(f"mission check's page: {checked['layers']}; mission check: {len(check_report['conflicts'])} conflicts, "
             f"{check_report['obstacles']} obstacles; export --as-written: {len(written)} waypoints")
    for row, p in zip(checked["table"], written):
        if abs(row[1] - p["geometry"]["coordinates"][0]) > 1e-7 or abs(row[2] - p["geometry"]["coordinates"][1]) > 1e-7:
            fail(f"mission check's waypoint {row[0]} is not export --as-written's")
    print(f"web map: {sum(drawn['layers'].values())} features in {len(drawn['layers'])} layers drawn; "
          f"{len(points)} waypoints equal mission export's; obstacle {obstacle} named by a click; "
          f"checked page: {len(written)} waypoints as written, {len(check_report['conflicts'])} conflicts; "
          f"simulated: {layers['track']} track stretches, {layers['detected']} objects found")


if __name__ == "__main__":
    if sys.argv[1] == "click":
        data, _ = page_data(sys.argv[2])
        feature = next(f for f in layer(data, "no_go")["features"] if f["properties"]["record"] == sys.argv[3])
        x, y = point_inside(feature)
        print(f"{x:.7f},{y:.7f}")
    elif sys.argv[1] == "pick":
        data, _ = page_data(sys.argv[2])
        chosen = [f for f in layer(data, "no_go")["features"] if f["properties"]["class"] == sys.argv[3]]
        feature = max(chosen, key=lambda f: max(len(r[0]) for r in polygons(f["geometry"])))
        x, y = point_inside(feature)
        print(f"{feature['properties']['record']} {x:.7f},{y:.7f}")
    elif sys.argv[1] == "pick-obstacle":
        data, _ = page_data(sys.argv[2])
        feature = layer(data, "obstacles")["features"][0]
        x, y = point_inside(feature)
        print(f"{feature['properties']['obstacle']} {x:.7f},{y:.7f}")
    elif sys.argv[1] == "check":
        check(sys.argv[2], sys.argv[3])
    elif sys.argv[1] == "check-mission":
        check_mission(sys.argv[2], sys.argv[3])
    else:
        check_chart(sys.argv[2], sys.argv[3])
