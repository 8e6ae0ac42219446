<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<context>
    <name>Airspace</name>
    <message numerus="yes">
        <source>%n day(s) ago</source>
        <translation>
            <numerusform>%n day ago</numerusform>
            <numerusform>%n days ago</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CommandBar</name>
    <message numerus="yes">
        <source>To %n ticked vehicle(s): %1</source>
        <translation>
            <numerusform>To %n ticked vehicle: %1</numerusform>
            <numerusform>To %n ticked vehicles: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Checklist: %n to do</source>
        <translation>
            <numerusform>Checklist: %n to do</numerusform>
            <numerusform>Checklist: %n to do</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MissionDifference</name>
    <message numerus="yes">
        <source>the vehicle holds %n waypoint(s), %1 were sent</source>
        <translation>
            <numerusform>the vehicle holds %n waypoint, %1 were sent</numerusform>
            <numerusform>the vehicle holds %n waypoints, %1 were sent</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n action(s), sent %1</source>
        <translation>
            <numerusform>%n action, sent %1</numerusform>
            <numerusform>%n actions, sent %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>NfzConversion</name>
    <message numerus="yes">
        <source>its prism has %n corner(s); a polygon needs 3</source>
        <translation>
            <numerusform>its prism has %n corner; a polygon needs 3</numerusform>
            <numerusform>its prism has %n corners; a polygon needs 3</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n ring(s)</source>
        <translation>
            <numerusform>%n ring</numerusform>
            <numerusform>%n rings</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>a server zone is one polygon without holes (this one has %n part(s), %1)</source>
        <translation>
            <numerusform>a server zone is one polygon without holes (this one has %n part, %1)</numerusform>
            <numerusform>a server zone is one polygon without holes (this one has %n parts, %1)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>its polygon has %n corner(s); it needs 3</source>
        <translation>
            <numerusform>its polygon has %n corner; it needs 3</numerusform>
            <numerusform>its polygon has %n corners; it needs 3</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message numerus="yes">
        <source>%n more damaged block(s) skipped</source>
        <translation>
            <numerusform>%n more damaged block skipped</numerusform>
            <numerusform>%n more damaged blocks skipped</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RoutePanel</name>
    <message numerus="yes">
        <source>%n batteries</source>
        <translation>
            <numerusform>%n battery</numerusform>
            <numerusform>%n batteries</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RouteValidator</name>
    <message numerus="yes">
        <source>%n AMSL altitude(s), the first at %1, were not checked against the route&apos;s limits: the take-off elevation is unknown.</source>
        <translation>
            <numerusform>%n AMSL altitude, at %1, was not checked against the route&apos;s limits: the take-off elevation is unknown.</numerusform>
            <numerusform>%n AMSL altitudes, the first at %1, were not checked against the route&apos;s limits: the take-off elevation is unknown.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SegmentPlanner</name>
    <message numerus="yes">
        <source>Orbit of %1 m radius: %n lap(s) of %2 points, %3</source>
        <translation>
            <numerusform>Orbit of %1 m radius: %n lap of %2 points, %3</numerusform>
            <numerusform>Orbit of %1 m radius: %n laps of %2 points, %3</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>UploadReview</name>
    <message numerus="yes">
        <source>%1 (and %n more error(s)) Fix them before %2.</source>
        <translation>
            <numerusform>%1 (and %n more error) Fix them before %2.</numerusform>
            <numerusform>%1 (and %n more errors) Fix them before %2.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The route has %n warning(s):</source>
        <translation>
            <numerusform>The route has %n warning:</numerusform>
            <numerusform>The route has %n warnings:</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ValidationGate</name>
    <message numerus="yes">
        <source>%1 refused: the route has %n validation error(s). %2 Fix them, or override explicitly.</source>
        <translation>
            <numerusform>%1 refused: the route has %n validation error. %2 Fix them, or override explicitly.</numerusform>
            <numerusform>%1 refused: the route has %n validation errors. %2 Fix them, or override explicitly.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>VciFenceBuilder</name>
    <message numerus="yes">
        <source>fence: %1 of the route&apos;s own, %n airspace zone(s) near it; on a breach the vehicle will %2</source>
        <translation>
            <numerusform>fence: %1 of the route&apos;s own, %n airspace zone near it; on a breach the vehicle will %2</numerusform>
            <numerusform>fence: %1 of the route&apos;s own, %n airspace zones near it; on a breach the vehicle will %2</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>WaypointTable</name>
    <message numerus="yes">
        <source>%n selected:</source>
        <translation>
            <numerusform>%n selected:</numerusform>
            <numerusform>%n selected:</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::client::CommandPolicy</name>
    <message numerus="yes">
        <source>Start the mission on %1 (%n waypoint(s))?</source>
        <translation>
            <numerusform>Start the mission on %1 (%n waypoint)?</numerusform>
            <numerusform>Start the mission on %1 (%n waypoints)?</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::client::MissionController</name>
    <message numerus="yes">
        <source>%1%n segment(s)</source>
        <translation>
            <numerusform>%1%n segment</numerusform>
            <numerusform>%1%n segments</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::client::MissionUploader</name>
    <message numerus="yes">
        <source>Uploaded to %1: %n waypoint(s).</source>
        <translation>
            <numerusform>Uploaded to %1: %n waypoint.</numerusform>
            <numerusform>Uploaded to %1: %n waypoints.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::client::RouteDocument</name>
    <message numerus="yes">
        <source>Imported %n segment(s) from %1.</source>
        <translation>
            <numerusform>Imported %n segment from %1.</numerusform>
            <numerusform>Imported %n segments from %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::client::RoutePreparation</name>
    <message numerus="yes">
        <source>Processed for %1: %n waypoint(s) to fly.</source>
        <translation>
            <numerusform>Processed for %1: %n waypoint to fly.</numerusform>
            <numerusform>Processed for %1: %n waypoints to fly.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::client::VehicleGroup</name>
    <message numerus="yes">
        <source>%1 (%n waypoint(s))</source>
        <translation>
            <numerusform>%1 (%n waypoint)</numerusform>
            <numerusform>%1 (%n waypoints)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Arm %n vehicle(s): %1? Their motors may start.</source>
        <translation>
            <numerusform>Arm %n vehicle: %1? Their motors may start.</numerusform>
            <numerusform>Arm %n vehicles: %1? Their motors may start.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Disarm %n vehicle(s): %1? One in the air would fall.</source>
        <translation>
            <numerusform>Disarm %n vehicle: %1? One in the air would fall.</numerusform>
            <numerusform>Disarm %n vehicles: %1? One in the air would fall.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Take off with %n vehicle(s) to their altitudes above home: %1?</source>
        <translation>
            <numerusform>Take off with %n vehicle to their altitudes above home: %1?</numerusform>
            <numerusform>Take off with %n vehicles to their altitudes above home: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Start or resume the mission on %n vehicle(s): %1?</source>
        <translation>
            <numerusform>Start or resume the mission on %n vehicle: %1?</numerusform>
            <numerusform>Start or resume the mission on %n vehicles: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Pause %n vehicle(s) where they are: %1?</source>
        <translation>
            <numerusform>Pause %n vehicle where they are: %1?</numerusform>
            <numerusform>Pause %n vehicles where they are: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Land %n vehicle(s) where they are: %1?</source>
        <translation>
            <numerusform>Land %n vehicle where they are: %1?</numerusform>
            <numerusform>Land %n vehicles where they are: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Send %n vehicle(s) home: %1?</source>
        <translation>
            <numerusform>Send %n vehicle home: %1?</numerusform>
            <numerusform>Send %n vehicles home: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Switch %n vehicle(s) to %2: %1?</source>
        <translation>
            <numerusform>Switch %n vehicle to %2: %1?</numerusform>
            <numerusform>Switch %n vehicles to %2: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %2 of %n vehicle(s) answered — %3.</source>
        <translation>
            <numerusform>%1: %2 of %n vehicle answered — %3.</numerusform>
            <numerusform>%1: %2 of %n vehicles answered — %3.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::coverage::PhotoSurvey</name>
    <message numerus="yes">
        <source>%n geotagged copies, geo.txt and geotags.csv written to %1.</source>
        <translation>
            <numerusform>%n geotagged copy, geo.txt and geotags.csv written to %1.</numerusform>
            <numerusform>%n geotagged copies, geo.txt and geotags.csv written to %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n photos placed on %2&apos;s track (camera clock %3 s).</source>
        <translation>
            <numerusform>%1 of %n photo placed on %2&apos;s track (camera clock %3 s).</numerusform>
            <numerusform>%1 of %n photos placed on %2&apos;s track (camera clock %3 s).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 % of %2 m² seen by at least %3 images; forward overlap %4, side %5; %6 per pixel; %n hole(s).</source>
        <translation>
            <numerusform>%1 % of %2 m² seen by at least %3 images; forward overlap %4, side %5; %6 per pixel; %n hole.</numerusform>
            <numerusform>%1 % of %2 m² seen by at least %3 images; forward overlap %4, side %5; %6 per pixel; %n holes.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>&quot;Re-fly the gaps&quot; is open in the mission editor: %n area scan(s) at %1 m, %2/%3 % overlap.</source>
        <translation>
            <numerusform>&quot;Re-fly the gaps&quot; is open in the mission editor: %n area scan at %1 m, %2/%3 % overlap.</numerusform>
            <numerusform>&quot;Re-fly the gaps&quot; is open in the mission editor: %n area scans at %1 m, %2/%3 % overlap.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n photos placed where %2 took them, paired with its photo events (camera clock %3 s off).</source>
        <translation>
            <numerusform>%1 of %n photo placed where %2 took it, paired with its photo events (camera clock %3 s off).</numerusform>
            <numerusform>%1 of %n photos placed where %2 took them, paired with its photo events (camera clock %3 s off).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n photo(s) the vehicle took are not in the folder.</source>
        <translation>
            <numerusform>%n photo the vehicle took is not in the folder.</numerusform>
            <numerusform>%n photos the vehicle took are not in the folder.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::FlightLogWriter</name>
    <message numerus="yes">
        <source>Recording to %1 resumed; %n value(s) recorded while it failed could not be kept.</source>
        <translation>
            <numerusform>Recording to %1 resumed; %n value recorded while it failed could not be kept.</numerusform>
            <numerusform>Recording to %1 resumed; %n values recorded while it failed could not be kept.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::maptiles::OfflineMaps</name>
    <message numerus="yes">
        <source>The open route (%n point(s)) and %1 m around it</source>
        <translation>
            <numerusform>The open route (%n point) and %1 m around it</numerusform>
            <numerusform>The open route (%n points) and %1 m around it</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>A drawn area (%n corner(s))</source>
        <translation>
            <numerusform>A drawn area (%n corner)</numerusform>
            <numerusform>A drawn area (%n corners)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::mission::RouteEditor</name>
    <message numerus="yes">
        <source>Move %n segment(s)</source>
        <translation>
            <numerusform>Move %n segment</numerusform>
            <numerusform>Move %n segments</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>This figure keeps at least %n point(s).</source>
        <translation>
            <numerusform>This figure keeps at least %n point.</numerusform>
            <numerusform>This figure keeps at least %n points.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 needs at least %n point(s)%2.</source>
        <translation>
            <numerusform>%1 needs at least %n point%2.</numerusform>
            <numerusform>%1 needs at least %n points%2.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::preflight::VehicleChecklist</name>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errors</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::resume::MissionResume</name>
    <message numerus="yes">
        <source>%1 stopped flying to waypoint %2 of %3, after %n photo(s).</source>
        <translation>
            <numerusform>%1 stopped flying to waypoint %2 of %3, after %n photo.</numerusform>
            <numerusform>%1 stopped flying to waypoint %2 of %3, after %n photos.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::ui::RasterFileCheck</name>
    <message numerus="yes">
        <source>%n file(s) left out, the others are used:</source>
        <translation>
            <numerusform>%n file left out, the others are used:</numerusform>
            <numerusform>%n files left out, the others are used:</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>and %n more (in the log)</source>
        <translation>
            <numerusform>and %n more (in the log)</numerusform>
            <numerusform>and %n more (in the log)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::ui::TileManager</name>
    <message numerus="yes">
        <source>%1: loading %n tile(s)</source>
        <translation>
            <numerusform>%1: loading %n tile</numerusform>
            <numerusform>%1: loading %n tiles</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %n tile(s) missing — %2</source>
        <translation>
            <numerusform>%1: %n tile missing — %2</numerusform>
            <numerusform>%1: %n tiles missing — %2</numerusform>
        </translation>
    </message>
</context>
</TS>
