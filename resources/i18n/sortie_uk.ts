<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="uk">
<context>
    <name>ActionEditor</name>
    <message>
        <source>The selected waypoints have different actions: these are the first one&apos;s. An edit applies where they match; an added action goes to all.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent by the server; kept and sent back unchanged.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add action</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove all</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>AtomicFile</name>
    <message>
        <source>Cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>AutosaveWriter</name>
    <message>
        <source>Cannot remove %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CommandBar</name>
    <message>
        <source>Are you sure?</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>To %n ticked vehicle(s): %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Untick all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disarm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Take off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Climb to %1 m above home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Auto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fly the uploaded mission</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Land</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Return home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Go here…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Then click on the map where the vehicle should fly</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a vehicle on the map or in the list; tick several to command them together.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CommandLogView</name>
    <message>
        <source>Command log</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ComparisonPanel</name>
    <message>
        <source>Compare with a route</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Routes (*.sortie *.plan *.waypoints *.wpl *.txt)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare with route…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>leg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>samples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cross-track max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mean</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>altitude max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reached</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FleetRoutesList</name>
    <message>
        <source>Routes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 flight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 flight · %2 flown · %3 left</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FlightLogSettingsDialog</name>
    <message>
        <source>Flight logs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Holds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recording to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A log up to (MB)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The folder up to (MB)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0: no limit. A log over its size continues in a new part; beyond the folder&apos;s size the oldest logs are deleted, never the one being written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>InstrumentPanel</name>
    <message>
        <source>%1 (%2, %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No vehicle chosen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Altitude AGL</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Altitude AMSL</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ground speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Vertical speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Battery</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>GPS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fix %1, %2 satellites</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Armed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ARMED</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>disarmed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (no data)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, %2 Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Flight time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>To home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mission</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>LoginPage</name>
    <message>
        <source>Connect to a UgCS server</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Server (host:port)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Host name or address and HCI port of the UgCS server</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remember the password on this computer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kept in this computer&apos;s keyring for this server and user, never in a file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Log in (Enter in the password field)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Logged in as %1 at %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Main</name>
    <message>
        <source>Sortie</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Login</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mission</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live telemetry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Map…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the map source (Ctrl+M)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offline…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Download the web map of an area for work without a network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Logs…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where flight logs are recorded, and how much they may take</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ft, mph</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>m, m/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch between metric and imperial units</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keyboard shortcuts (F1)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MapPane</name>
    <message>
        <source>Zoom in (+, wheel)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom out (−, wheel)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MapSourceDialog</name>
    <message>
        <source>Map source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offline base map (land outlines, always available)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Web tiles from a URL template</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{z}, {x} and {y} (or {-y}) are replaced per tile; {s} by a subdomain</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MBTiles file (offline raster tiles)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>/path/to/area.mbtiles</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MissionPage</name>
    <message>
        <source>Zones (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click the centre line (%1 so far)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click the corners of the area (%1 so far)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click where it goes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Create</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>battery change</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no return</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>OfflineMapsDialog</name>
    <message>
        <source>Offline maps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a web tile server in Map source first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The open route</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>and</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>m around it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The map&apos;s view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pack file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Attribution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>As the provider&apos;s usage policy asks, e.g. © OpenStreetMap contributors</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cache only: the map never uses the network (the pack, then the disk cache)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Download</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source> in %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disarm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Take off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Auto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Guided</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Manual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Land</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Return home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 min %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 km</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>That vehicle is not in this log (it holds %1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no vehicle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Route &quot;%1&quot; has fewer than two waypoints: there is nothing to compare.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no track in this log to compare with.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Route &quot;%1&quot; does not match %2: its waypoints are %3 km from anywhere %2 flew in this log.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 flown by %2, %3 to %4
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
waypoint  reached                    closest
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
leg      samples  cross-track max  mean      altitude max  mean
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
total: %1 reached, %2 missed; cross-track max %3, mean %4; altitude max %5, mean %6
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: no such file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cannot be opened: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no Sortie flight log header</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not a Sortie flight log (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the vehicles cannot be read: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the vehicle list is damaged: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>block %1 (after %2 good ones, %3) is damaged: %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at the start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown vehicle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped after %1 good blocks (%2): %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the telemetry cannot be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the events stop after %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the events cannot be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the routes stop early: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the routes cannot be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file:     %1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>span:     %1 to %2 (%3 s)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DAMAGED:  read up to the last good record; %1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vehicles: %1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>    route uploaded %1: %2 waypoints
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
events:   %1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (failed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a replayed vehicle takes no commands</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ReplayTimeline</name>
    <message>
        <source>Open a flight log</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Flight logs (*.sortielog)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export tracks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open log…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Server history…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>REPLAY — %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Play</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Previous event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jump to event (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loading plots…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back to live</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RestoreDialog</name>
    <message>
        <source>Autosaved edits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore one of %1 unsaved routes?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore unsaved edits?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sortie did not close normally. These routes had unsaved edits, saved automatically. Choose one to see its changes; the others are kept and offered again at the next start.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sortie did not close normally. Edits of “%1” were saved automatically at %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — saved %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>It belongs to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Changes since the last save:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Discard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start without these edits (the file is kept as a backup)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Later</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep them and decide after signing in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RoutePanel</name>
    <message>
        <source>Import a route</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Routes (*.sortie *.plan *.waypoints *.txt *.kml *.kmz)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The vehicle&apos;s energy profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Energy profiles (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export the route</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sortie (*.sortie)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>QGroundControl plan (*.plan)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waypoint list (*.waypoints)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>KML (*.kml)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DJI Pilot 2 route, WPML (*.kmz)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a route…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save on the server, under its lock (Ctrl+S)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo %1 (Ctrl+Z)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Redo %1 (Ctrl+Shift+Z)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete the selected waypoints (Del)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Area scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw an area to scan: click its corners on the map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone checks…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Which no-fly zones the server&apos;s processing refuses the route for</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refuse crossing aerodrome zones</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refuse crossing custom zones</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Process</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Prepare the route for the chosen vehicle, as the upload will, and show what it would fly (Ctrl+P)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Vehicle…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Yours (version %1, edited) against theirs (version %2, grey on the map):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>They changed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep mine (overwrite theirs)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Take theirs (undo brings mine back)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waypoints</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Photos</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Conflicts with other vehicles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1:%2  leg %3 · %4 (%5): %6 m across, %7 m in height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flying</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>uploaded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Energy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 Wh</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n batteries</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>%1 % left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No return</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown: no home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>after %1 (leg %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none: home in reach</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Beyond this point of the route, flying straight home no longer lands with the reserve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load an energy profile to see whether the battery lasts.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unnamed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The vehicle&apos;s energy profile: a JSON file, e.g. from sortie-log fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wind speed, m/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>m/s from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The direction the wind blows from, degrees clockwise from north</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select the segment</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SegmentEditor</name>
    <message>
        <source>Radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Advanced parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 m high · %2 cm/px · footprint %3 × %4 m · passes %5 m apart · photo every %6 m · %7 photos</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ServerAction</name>
    <message>
        <source>Server action</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ServerHistoryDialog</name>
    <message>
        <source>Server history</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Vehicle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From (UTC)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>To (UTC)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last hour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fetch and replay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ShortcutHelp</name>
    <message>
        <source>Keyboard shortcuts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On the map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Esc closes this help.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Shortcuts</name>
    <message>
        <source>Pan the map (Shift: faster)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom in / out (also the mouse wheel and pinch)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drag</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pan the map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shift+Drag</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select waypoints in a rectangle (Ctrl+Shift adds)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a waypoint; on a leg: insert one; on a waypoint: select (Ctrl toggles, Shift extends)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drag a waypoint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move it, or the whole selection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show or hide this help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Login page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mission page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live telemetry page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the route on the server</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete the selected waypoints</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Process the route on the server</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the map source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Focus the map (then arrows and +/− move it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Full screen on or off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quit</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>StatusBar</name>
    <message>
        <source>zoom %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>TelemetryPage</name>
    <message>
        <source>Vehicles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No vehicles. Log in to a server or connect a VCI vehicle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Command together with the other ticked vehicles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Vehicle %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A vehicle reached directly over VCI: tcp://host:port or serial:///dev/ttyX?baud=57600</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show every vehicle on the map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Follow</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep the chosen vehicle in the middle of the map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fly %1 to %2?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Return home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Too close: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Airspace: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plot this field too</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>5 min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>30 min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove from the plot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All vehicles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare these fields across every vehicle</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>UploadQuestion</name>
    <message>
        <source>Upload the route?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload without saving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save and upload</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>WaypointTable</name>
    <message numerus="yes">
        <source>%n selected:</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>alt m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>m/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Altitude above ground (AGL) or above mean sea level (AMSL)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heights:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>as set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all AMSL</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all AGL</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AMSL and AGL are converted through the ground under each waypoint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ground: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>#</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Latitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AMSL</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AGL</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ground</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Area scan</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ZonePanel</name>
    <message>
        <source>Load zones</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zones (*.geojson *.json *.kml *.plan)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zones (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click the corners on the map, then Create</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Circle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click the centre on the map; drag its handle for the radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Create</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Checked against the route when ticked</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 · %2 – %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Floor (m)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ground</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ceiling (m)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Above</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove zone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warn within (m)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie</name>
    <message>
        <source>Sortie: mission planning and live telemetry for UgCS servers and VCI vehicles.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start the built-in simulator on this computer and connect to it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>UgCS server to connect to.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User name to log in with.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect a vehicle directly over VCI: tcp://host:port or serial:///dev/ttyX?baud=57600.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print the start-up time and memory in use, then quit (for benchmarks).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Folder for autosaved edits (default: the application data folder; also SORTIE_AUTOSAVE_DIR).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SRTM .hgt terrain tiles (a tile or a folder), asked before the server (also the setting terrain/demFolder).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>An ADS-B receiver&apos;s SBS-1 feed for manned traffic, as dump1090 serves it (port 30003); also the setting traffic/sbsAddress.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ServerZones</name>
    <message>
        <source>Zones across the ±180° meridian are not supported; the view was not asked about.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The server&apos;s no-fly zones could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not saved: not connected to the server.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; cannot be saved on the server: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not saved: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not saved: it is locked (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was saved, but the server&apos;s answer cannot be read back: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: it is not on the server.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: aerodrome zones are the server&apos;s own.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: not connected to the server.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: it is locked (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneAlertMonitor</name>
    <message>
        <source>%1 is inside &apos;%2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 enters &apos;%2&apos;%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is outside &apos;%2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 leaves &apos;%2&apos;%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (its height there is unknown)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneEditor</name>
    <message>
        <source>A zone needs at least three corners.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This polygon cannot be a zone: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw zone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A circular zone needs a centre and a radius above 0 m.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw circular zone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no drawn zone %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove zone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>That is not a position.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A circle has only its centre to move.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The zone has no corner %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move zone corner</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A corner can be added only to a polygon, on one of its edges.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add zone corner</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A zone keeps at least three corners.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove zone corner</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The radius must be above 0 m.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Only a circular zone has a radius.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A zone needs a name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rename zone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A zone is an exclusion or an inclusion zone, not &quot;%1&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heights are AMSL, AGL or HOME, not &quot;%1&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A floor or ceiling is a number of metres, or empty.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The ceiling (%1 m) must be above the floor (%2 m).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone floor and ceiling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The zone would not be a valid polygon: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zone %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::client</name>
    <message>
        <source>%1 Fix it before %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (and %n more error(s)) Fix them before %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>uploading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>saving</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::client::AutosaveRecovery</name>
    <message>
        <source>The autosaved edits in %1 cannot be read: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The autosaved edits in %1 cannot be read (%2). The file was kept as %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The autosaved edits in %1 cannot be read (%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Untitled route</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>route %1, version %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> as %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The route open now has unsaved edits, and restoring would replace it: save or undo them first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 as %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>These edits belong to route %1 on %2, and saving them updates that route. Sign in to %2 to restore them: choose Later, sign in, and they are offered again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>These edits belong to route %1 on %2, but this session is signed in to %3 as %4. Sign out and sign in to %2 to restore them; until then they are kept and offered again at each start.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore autosaved edits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The autosave %1 could not be moved aside.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::client::CommandPolicy</name>
    <message>
        <source>Manual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Taking off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Auto (fly the mission)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Guided</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Land</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Return home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the vehicle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arm %1? Its motors may start.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disarm %1? It may be in the air, and would fall.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Take off with %1 to %2 m above home?</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Start the mission on %1 (%n waypoint(s))?</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Start the mission on %1? Sortie has not seen its mission.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::client::ConnectionController</name>
    <message>
        <source>connection lost; attempt %1 in %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reconnected in a new session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The server address is not usable: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter a user name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1. Check the server&apos;s address and this computer&apos;s network.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1. Is the UgCS server running, and is the port right?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrong user name or password (%1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1. This server cannot be used with Sortie.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The server&apos;s licence allows no more connections (%1). Close another client or extend the licence.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The server did not answer in time (%1). It may be overloaded or not a UgCS server.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The connection was closed (%1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The server answered something Sortie cannot use (%1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The server refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::client::FleetRoutes</name>
    <message>
        <source>Unnamed route</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>planned</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>uploaded %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>paused: waypoint %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flying: waypoint %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flown</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::client::MissionController</name>
    <message>
        <source>Reading the server&apos;s routes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The server&apos;s routes could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1%n segment(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Reading the server&apos;s vehicles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opening the route</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The route could not be opened: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The route cannot be edited here: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened %1 (version %2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected: your edits are kept; save again when the connection is back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wait until %1 is done.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locking the route</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not saved: the route is locked (%1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the server&apos;s copy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Someone else saved this route on the server (version %1) after you opened it (version %2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved, but the server&apos;s answer cannot be read back: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1 (version %2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Take the server&apos;s version</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This is the server&apos;s copy now. Undo brings your edits back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This route was deleted on the server. Your copy stays open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Updated from the server (version %1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Someone else saved this route on the server (version %1) while you were editing it.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::client::MissionUploader</name>
    <message>
        <source>Checking the route</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waiting for your answer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Processing for %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Taking control of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Uploading to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Releasing %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the mission back from %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>upload &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>route</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload to %1 failed: the vehicle is gone (its connection was closed).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the vehicle is gone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not uploaded: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Too late to cancel: the mission is being sent to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload to %1 cancelled; nothing was sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload to %1 failed: the vehicle has no link.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not uploaded to %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the route&apos;s fence is not sent: %1 keeps no fence (HCI)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload to %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Uploaded to %1, but it could not be read back: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Uploaded to %1, but it holds something else: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Uploaded to %1: %n waypoint(s).</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Note: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::client::RouteAutosave</name>
    <message>
        <source>No free autosave slot in %1: edits are not autosaved.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::client::RouteDocument</name>
    <message>
        <source>Import failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import failed: %1 holds no route.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Imported %n segment(s) from %1.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>The file holds %1 routes; this is the first (&quot;%2&quot;).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not representable there: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::client::RoutePreparation</name>
    <message>
        <source>Choose the vehicle to %1 for.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>process the route</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no link.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Processing for %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not processed for %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Processed for %1: %n waypoint(s) to fly.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>upload</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>An upload is waiting for your answer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wait until %1 is done.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::client::UploadReview</name>
    <message>
        <source>The route has edits that are not saved: the vehicle would fly what is on screen, not what the server holds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The route has %n warning(s):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload to %1?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::client::VehicleFleet</name>
    <message>
        <source>%1: %2 done.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 failed: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The server&apos;s vehicles could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not a VCI address: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>go to %1, %2 at %3 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: flying to the clicked point.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: go-to failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::client::VehicleGroup</name>
    <message>
        <source>%1 (%2 m)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1 (%n waypoint(s))</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Arm %n vehicle(s): %1? Their motors may start.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Disarm %n vehicle(s): %1? One in the air would fall.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Take off with %n vehicle(s) to their altitudes above home: %1?</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Start or resume the mission on %n vehicle(s): %1?</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Pause %n vehicle(s) where they are: %1?</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Land %n vehicle(s) where they are: %1?</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Send %n vehicle(s) home: %1?</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Switch %n vehicle(s) to %2: %1?</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>not sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 waiting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1: %2 of %n vehicle(s) answered — %3.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::deconfliction::FleetConflictRule</name>
    <message>
        <source>%1, flying &quot;%2&quot; (its leg %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1&apos;s uploaded &quot;%2&quot; (its leg %3) if it starts now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Leg %1 comes within %2 m across and %3 m in height of %4, %5 after the start%6.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (heights in different frames: judged across only)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::deconfliction::ProximityMonitor</name>
    <message>
        <source>now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 and traffic %2: closest %3, %4 across and %5 in height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 and %2: closest %3, %4 across and %5 in height</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::endurance::EnduranceAdvisory</name>
    <message>
        <source>No vehicle chosen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No energy profile: choose the vehicle&apos;s profile file on the mission page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The vehicle reports no remaining battery</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The vehicle reports no home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The vehicle reports no position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No mission on board</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The vehicle cannot make headway home against the wind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Battery at end of route: %1 · home needs %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Battery: time to come home — no headway home against the wind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Battery: time to come home — %1 left, home needs %2: the %3 reserve is being used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Battery: time to come home — %1 left, home needs %2 and the reserve %3: %4 to spare</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Return %1 home now? %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ComparisonController</name>
    <message>
        <source>Open a flight log first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 holds no route.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the vehicle to compare on the map or in the list.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 on &quot;%2&quot;: %3 of %4 waypoints reached; cross-track max %5 m, mean %6 m; altitude max %7 m</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::FlightLogWriter</name>
    <message>
        <source>%1: the log cannot use a write-ahead journal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recording to %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recording could not continue in %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::FlightRecorder</name>
    <message>
        <source>The flight log %1 cannot be written: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recording started</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recording stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Route of 1 waypoint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Route of %1 waypoints</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Armed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disarmed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::RecordingSettings</name>
    <message>
        <source>In force: %1; %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a log up to %1 MB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>logs of any size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the folder up to %1 MB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the folder without limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A log&apos;s size must be between 1 and %1 MB, or 0 for no limit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The folder&apos;s size must be between 1 and %1 MB, or 0 for no limit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The folder must hold at least one whole log: make its limit at least a log&apos;s size (%1 MB).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 in 1 log</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 in %2 logs</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ReplayController</name>
    <message>
        <source>%1 of 1 vehicle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 vehicles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No log is open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an export format (gpx, kml or csv).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 could not be written: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ServerHistory</name>
    <message>
        <source>not connected to a server</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The server&apos;s history could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ServerHistoryRequest</name>
    <message>
        <source>The server lists no vehicles: connect to a server first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a vehicle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The start &quot;%1&quot; is not a time like %2 (UTC).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The end &quot;%1&quot; is not a time like %2 (UTC).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The start must be before the end.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The start is in the future.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>At most 24 hours at a time.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The server has no telemetry of %1 from %2 to %3 UTC.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no replay to show it in.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ServerRecording</name>
    <message>
        <source>logged in to %1 as %2; recording to %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>server: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 vehicle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 vehicles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>log closed: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::maptiles</name>
    <message>
        <source>%1: &apos;%2&apos; is not a zoom level (0 to 30).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bounds: &apos;%1&apos; is not west,south,east,north in degrees.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::maptiles::MbTilesFile</name>
    <message>
        <source>No MBTiles file is set.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The MBTiles file %1 does not exist.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot open the MBTiles file %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not an MBTiles file Sortie can write: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not an MBTiles file (it has no tiles table).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The MBTiles file %1 has no readable metadata: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write to the MBTiles file %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write the metadata of %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading tile %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing %1 tiles to %2 failed: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the tiles of %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::maptiles::MbTilesMetadata</name>
    <message>
        <source>minzoom %1 is above maxzoom %2.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::maptiles::OfflineMaps</name>
    <message>
        <source>No route is open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The open route has no waypoints to take the area from.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The route is a single point: give a margin around it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The open route (%n point(s)) and %1 m around it</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>The map&apos;s view is not an area (%1 to %2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The map&apos;s view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The lowest zoom is above the highest.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose an area.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 tiles, about %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (at this pack&apos;s mean of %1 a tile)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (assuming %1 a tile)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>: more than the limit of %1 tiles, choose a smaller area or fewer zoom levels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a web tile server in Map source first: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 tiles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> · %1 already in the pack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> · %1 not stored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> · paused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> · done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> · stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> · failed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::maptiles::TileArea</name>
    <message>
        <source>The area is not a valid latitude/longitude box (south %1, west %2, north %3, east %4).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>An area needs at least three corners (it has %1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corner %1 of the area is not a latitude/longitude (%2, %3).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The area&apos;s edge from corner %1 crosses the antimeridian: draw it as two areas.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::maptiles::TilePrefetch</name>
    <message>
        <source>No area is chosen.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The zoom range %1 to %2 is not within 0 to %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The area needs %1 tiles, more than the limit of %2: choose a smaller area or fewer zoom levels.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tiles from %1, taken offline by %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not an image (%1, %2 bytes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer within %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (after %2 attempts)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::maptiles::TileUrlTemplate</name>
    <message>
        <source>No tile URL template is set.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The tile URL template is not a valid URL: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The tile URL template must start with http://, https:// or file://.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The tile URL template needs {z}, {x} and {y} (or {-y}).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::mission</name>
    <message>
        <source>WP %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scan %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>return home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::mission::RouteDiff</name>
    <message>
        <source>No changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 change: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 changes: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> and %1 more</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>name %1 → %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 → %3 %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vehicle profile %1 → %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vehicle profile %1 changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>failsafe actions changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>home set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>home removed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>home moved %1 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>home altitude %1 → %2 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>end action %1 → %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 removed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 added</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 moved %2 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>altitude of %1 %2 m %3 → %4 m %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>altitude of %1 %2 → %3 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>speed of %1 %2 → %3 m/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>actions of %1: %2 → %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>turn at %1 %2 → %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>acceptance radius of %1 %2 → %3 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 → %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>figure of %1 reshaped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 %3 → %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 removed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>actions of %1 changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>area of %1 reshaped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>area of %1 reshaped (%2 → %3 corners)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 %3 → %4 %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>altitude of %1 now %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 now flies by ground sample distance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 now flies by altitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>camera of %1 %2 → %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>camera of %1 changed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::mission::RouteEditor</name>
    <message>
        <source>Nothing is selected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>That is not a valid position.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no row %1 to insert at.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add waypoint %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A move needs one position per waypoint.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no row %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Move %n segment(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Row %1 is not a waypoint.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The altitude needs a number.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set altitude to %1 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set altitude type to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Row %1 keeps its height %2: set it as %2, or change its altitude type first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waypoint %1 is planned %2 and there is no terrain data under it: a height %3 cannot be converted.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set altitude to %1 m %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set turn type to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No selected segment has a parameter &quot;%1&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no action &quot;%1&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add action: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove action</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no action &quot;%1&quot; with these values.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit action: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear actions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>An area scan needs at least three corners that enclose an area.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add area scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Segment %1 has no point %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move point %1 of segment %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Segment %1 has no edge there.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a point to segment %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>This figure keeps at least %n point(s).</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Remove point %1 of segment %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A radius is above 0 m.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Segment %1 is no circle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set the radius of segment %1 to %2 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A point segment needs one valid position.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sortie has no description of the algorithm %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1 needs at least %n point(s)%2.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source> enclosing an area</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A route has no setting &quot;%1&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs a number.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set route %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::mission::SegmentEditorModel</name>
    <message>
        <source>A parameter Sortie has no description of: kept and sent as typed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (vehicle profile)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs a number, not &quot;%2&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::mission::SegmentPreview</name>
    <message>
        <source>This segment cannot be planned.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::mission::WaypointActionsModel</name>
    <message>
        <source>Actions at waypoint %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actions at %1 waypoints</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no action &quot;%1&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This action has no field &quot;%1&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::secrets::PasswordVault</name>
    <message>
        <source>the keyring did not answer</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::traffic::SbsFeed</name>
    <message>
        <source>no answer within %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the receiver closed the connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not host:port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>receiver off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>receiver: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>receiver: connecting to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>receiver %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>receiver: %1; again in %2 s</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::AppSettings</name>
    <message>
        <source>The password an earlier version kept in the settings file is now in the keyring.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The password an earlier version kept in the settings file was erased from it; the keyring refused it (%1), so it is not remembered.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The keyring refused the password (%1): it is not remembered.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The remembered password could not be read from the keyring (%1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The password could not be removed from the keyring (%1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No keyring is reachable, so the password cannot be remembered (%1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The password an earlier version kept in the settings file was erased from it.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::AttitudeIndicator</name>
    <message>
        <source>no attitude</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::ConflictLayer</name>
    <message>
        <source>%1 at %2:%3, %4 m / %5 m</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::DisplayUnits</name>
    <message>
        <source>%1 mi</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 ft</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 km</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 mph</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 m/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 V</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>link lost</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::ElevationProfileView</name>
    <message>
        <source>Leg %1 · %2 · ground %3 · altitude %4 · clearance %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add two waypoints to see the terrain profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No terrain source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ground: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lowest clearance %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>clearance unknown</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::EnduranceLayer</name>
    <message>
        <source>Battery change</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Battery change needed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No return</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::FlightStatus</name>
    <message>
        <source>mission complete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>waypoint %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 waypoint on board</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 waypoints on board</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no mission on board</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::MbTilesTileSource</name>
    <message>
        <source>MBTiles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No MBTiles file is set.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The MBTiles file has no tile %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tile %1 in the MBTiles file is not a raster image.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::OfflineTileSource</name>
    <message>
        <source>Offline base map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Land outlines: Natural Earth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The built-in land outlines could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::TelemetryPlot</name>
    <message>
        <source>−%1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No data yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a vehicle</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::TerrainProfileModel</name>
    <message>
        <source>no terrain source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no terrain data (tried: %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> · loading…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>under this waypoint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>under this segment&apos;s points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Asking for the ground %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No terrain data %1 (tried: %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ground %1, metres above sea level (EGM96), from %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; some points have no data (tried: %1)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::TileManager</name>
    <message>
        <source>Offline base map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — offline base map shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1: loading %n tile(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %n tile(s) missing — %2</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::ui::TrafficLayer</name>
    <message>
        <source>%1 ft</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> std</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> climbing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> descending</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::XyzTileSource</name>
    <message>
        <source>Web tiles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tile %1 is not an image.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tile %1 is neither in the offline pack nor in the cache (cache only: the network is not used).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tile %1 is not in the cache and the tile server is unreachable.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No tile file %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The tile server answered HTTP %1 for tile %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tile server unreachable (%1).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::ui::ZoneLayer</name>
    <message>
        <source>drawn on the map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2 zone)
Source: %3%4
Floor %5, ceiling %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
Not checked: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
Switched off: not checked</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sortie::vehicle::CommandLog</name>
    <message>
        <source>sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>alert</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2: %3 %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2: %3 %4: %5</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
