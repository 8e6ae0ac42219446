<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
<context>
    <name>ActionEditor</name>
    <message>
        <source>The selected waypoints have different actions: these are the first one&apos;s. An edit applies where they match; an added action goes to all.</source>
        <translation>Die ausgewählten Wegpunkte haben unterschiedliche Aktionen; angezeigt werden die des ersten. Eine Änderung gilt dort, wo sie übereinstimmen; eine hinzugefügte Aktion gilt für alle.</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Sent by the server; kept and sent back unchanged.</source>
        <translation>Vom Server gesendet; wird unverändert behalten und zurückgesendet.</translation>
    </message>
    <message>
        <source>Add action</source>
        <translation>Aktion hinzufügen</translation>
    </message>
    <message>
        <source>Remove all</source>
        <translation>Alle entfernen</translation>
    </message>
</context>
<context>
    <name>ActionVariants</name>
    <message>
        <source>%1 is either on or off</source>
        <translation>%1 ist entweder ein oder aus</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not one of its choices</source>
        <translation>%1: „%2“ ist keine der Auswahlmöglichkeiten</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation>%1: „%2“ ist keine Zahl</translation>
    </message>
    <message>
        <source>%1: %2 is not a whole number</source>
        <translation>%1: %2 ist keine ganze Zahl</translation>
    </message>
    <message>
        <source>%1: %2 is below %3 %4</source>
        <translation>%1: %2 liegt unter %3 %4</translation>
    </message>
    <message>
        <source>%1: %2 is above %3 %4</source>
        <translation>%1: %2 liegt über %3 %4</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>Take a photo</source>
        <translation>Foto aufnehmen</translation>
    </message>
    <message>
        <source>Start video</source>
        <translation>Video starten</translation>
    </message>
    <message>
        <source>Stop video</source>
        <translation>Video stoppen</translation>
    </message>
    <message>
        <source>Toggle video</source>
        <translation>Video umschalten</translation>
    </message>
    <message>
        <source>Photos by distance</source>
        <translation>Fotos nach Strecke</translation>
    </message>
    <message>
        <source>Every</source>
        <translation>Alle</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>Shots (0: until stopped)</source>
        <translation>Aufnahmen (0: bis zum Stopp)</translation>
    </message>
    <message>
        <source>Start after</source>
        <translation>Start nach</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <source>Photos by time</source>
        <translation>Fotos nach Zeit</translation>
    </message>
    <message>
        <source>Wait</source>
        <translation>Warten</translation>
    </message>
    <message>
        <source>For</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <source>Until the operator continues</source>
        <translation>Bis der Bediener fortsetzt</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Kurs</translation>
    </message>
    <message>
        <source>From the course</source>
        <translation>Relativ zur Flugrichtung</translation>
    </message>
    <message>
        <source>Point of interest</source>
        <translation>Interessenpunkt</translation>
    </message>
    <message>
        <source>Latitude</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Altitude</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <source>Altitude type</source>
        <translation>Höhenbezug</translation>
    </message>
    <message>
        <source>Above ground (AGL)</source>
        <translation>Über Grund (AGL)</translation>
    </message>
    <message>
        <source>Above sea level (AMSL)</source>
        <translation>Über dem Meeresspiegel (AMSL)</translation>
    </message>
    <message>
        <source>Gimbal and zoom</source>
        <translation>Gimbal und Zoom</translation>
    </message>
    <message>
        <source>Tilt (90: down)</source>
        <translation>Neigung (90: nach unten)</translation>
    </message>
    <message>
        <source>Roll</source>
        <translation>Rollen</translation>
    </message>
    <message>
        <source>Yaw</source>
        <translation>Gieren</translation>
    </message>
    <message>
        <source>Zoom level</source>
        <translation>Zoomstufe</translation>
    </message>
    <message>
        <source>Panorama</source>
        <translation>Panorama</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Pause per step</source>
        <translation>Pause pro Schritt</translation>
    </message>
    <message>
        <source>Rotation speed</source>
        <translation>Drehgeschwindigkeit</translation>
    </message>
    <message>
        <source>°/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <source>Clockwise</source>
        <translation>Im Uhrzeigersinn</translation>
    </message>
    <message>
        <source>Video</source>
        <translation>Video</translation>
    </message>
    <message>
        <source>Set servo</source>
        <translation>Servo setzen</translation>
    </message>
    <message>
        <source>Servo</source>
        <translation>Servo</translation>
    </message>
    <message>
        <source>PWM</source>
        <translation>PWM</translation>
    </message>
    <message>
        <source>Repeat servo</source>
        <translation>Servo wiederholen</translation>
    </message>
    <message>
        <source>Cycle time</source>
        <translation>Zykluszeit</translation>
    </message>
    <message>
        <source>Repeats</source>
        <translation>Wiederholungen</translation>
    </message>
    <message>
        <source>Switch to hover (VTOL)</source>
        <translation>In den Schwebeflug wechseln (VTOL)</translation>
    </message>
    <message>
        <source>Switch to fixed-wing</source>
        <translation>In den Flächenflug wechseln</translation>
    </message>
    <message>
        <source>Lidar recording</source>
        <translation>Lidar-Aufzeichnung</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>Aufzeichnung</translation>
    </message>
    <message>
        <source>Lidar calibration</source>
        <translation>Lidar-Kalibrierung</translation>
    </message>
    <message>
        <source>Distance</source>
        <translation>Distanz</translation>
    </message>
    <message>
        <source>Times</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <source>Hop</source>
        <translation>Hop</translation>
    </message>
    <message>
        <source>Descent altitude</source>
        <translation>Abstiegshöhe</translation>
    </message>
    <message>
        <source>Drop payload</source>
        <translation>Nutzlast abwerfen</translation>
    </message>
    <message>
        <source>Descent speed</source>
        <translation>Sinkgeschwindigkeit</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
</context>
<context>
    <name>Airspace</name>
    <message>
        <source>route fence</source>
        <translation>Geofence der Route</translation>
    </message>
    <message>
        <source>the open route</source>
        <translation>die geöffnete Route</translation>
    </message>
    <message>
        <source>%1 (kept as %2)</source>
        <translation>%1 (beibehalten als %2)</translation>
    </message>
    <message>
        <source>drawn</source>
        <translation>gezeichnet</translation>
    </message>
    <message>
        <source>server</source>
        <translation>Server</translation>
    </message>
    <message>
        <source>file</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>server zone %1, edited here</source>
        <translation>Serverzone %1, hier bearbeitet</translation>
    </message>
    <message>
        <source>today</source>
        <translation>heute</translation>
    </message>
    <message>
        <source>yesterday</source>
        <translation>gestern</translation>
    </message>
    <message numerus="yes">
        <source>%n day(s) ago</source>
        <translation>
            <numerusform>vor %n Tag</numerusform>
            <numerusform>vor %n Tagen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>AirspaceRule</name>
    <message>
        <source>floor %1, ceiling %2</source>
        <translation>Untergrenze %1, Obergrenze %2</translation>
    </message>
    <message>
        <source>at %1</source>
        <translation>bei %1</translation>
    </message>
    <message>
        <source>from %1 to %2</source>
        <translation>von %1 bis %2</translation>
    </message>
    <message>
        <source>; its height there is unknown (no terrain data), so it counts as inside</source>
        <translation>; ihre Höhe dort ist unbekannt (keine Geländedaten), daher gilt sie als innerhalb</translation>
    </message>
    <message>
        <source>Leg %1 passes within %2 of %3 &apos;%4&apos; (buffer %5).</source>
        <translation>Teilstrecke %1 kommt bis auf %2 an %3 „%4“ heran (Puffer %5).</translation>
    </message>
    <message>
        <source>exclusion zone</source>
        <translation>die Ausschlusszone</translation>
    </message>
    <message>
        <source>the edge of inclusion zone</source>
        <translation>den Rand der Einschlusszone</translation>
    </message>
    <message>
        <source>Leg %1 enters &apos;%2&apos; %3 (%4)</source>
        <translation>Teilstrecke %1 tritt %3 in „%2“ ein (%4)</translation>
    </message>
    <message>
        <source>Leg %1 leaves &apos;%2&apos; %3 (%4)</source>
        <translation>Teilstrecke %1 verlässt „%2“ %3 (%4)</translation>
    </message>
    <message>
        <source>Message: %1</source>
        <translation>Hinweis: %1</translation>
    </message>
    <message>
        <source>Reason: %1.</source>
        <translation>Grund: %1.</translation>
    </message>
    <message>
        <source>Authority: %1.</source>
        <translation>Behörde: %1.</translation>
    </message>
    <message>
        <source>Applies: %1.</source>
        <translation>Gilt: %1.</translation>
    </message>
    <message>
        <source>Leg %1 enters the prohibited zone &apos;%2&apos; (%3, volume %4) %5 (%6)</source>
        <translation>Teilstrecke %1 tritt %5 in die Verbotszone „%2“ ein (%3, Volumen %4) (%6)</translation>
    </message>
    <message>
        <source>Leg %1 enters &apos;%2&apos; (%3, volume %4) %5 (%6), which needs an authorisation; none is recorded</source>
        <translation>Teilstrecke %1 tritt %5 in „%2“ ein (%3, Volumen %4) (%6), wofür eine Genehmigung nötig ist; keine ist erfasst</translation>
    </message>
    <message>
        <source>Leg %1 enters &apos;%2&apos; (%3, volume %4) %5 (%6) under authorisation %7</source>
        <translation>Teilstrecke %1 tritt %5 in „%2“ ein (%3, Volumen %4) (%6), mit Genehmigung %7</translation>
    </message>
    <message>
        <source>Leg %1 enters the conditional zone &apos;%2&apos; (%3, volume %4) %5 (%6)</source>
        <translation>Teilstrecke %1 tritt %5 in die Zone mit Auflagen „%2“ ein (%3, Volumen %4) (%6)</translation>
    </message>
    <message>
        <source>Leg %1 passes through &apos;%2&apos; (%3, volume %4) %5 (%6), a zone with no restriction</source>
        <translation>Teilstrecke %1 führt %5 durch „%2“ (%3, Volumen %4) (%6), eine Zone ohne Einschränkung</translation>
    </message>
</context>
<context>
    <name>AlertBanner</name>
    <message>
        <source>Too close: %1</source>
        <translation>Zu nah: %1</translation>
    </message>
    <message>
        <source>Airspace: %1</source>
        <translation>Luftraum: %1</translation>
    </message>
    <message>
        <source>Return home</source>
        <translation>Rückkehr</translation>
    </message>
</context>
<context>
    <name>AlgorithmDefinition</name>
    <message>
        <source>%1 must be set</source>
        <translation>%1 muss gesetzt sein</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1: „%2“ ist keine Zahl</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a whole number</source>
        <translation>%1: „%2“ ist keine ganze Zahl</translation>
    </message>
    <message>
        <source>%1: %2 is below the minimum of %3</source>
        <translation>%1: %2 liegt unter dem Minimum von %3</translation>
    </message>
    <message>
        <source>%1: %2 is above the maximum of %3</source>
        <translation>%1: %2 liegt über dem Maximum von %3</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is neither true nor false</source>
        <translation>%1: „%2“ ist weder true noch false</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not one of its choices</source>
        <translation>%1: „%2“ ist keine der Auswahlmöglichkeiten</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; does not have the expected form</source>
        <translation>%1: „%2“ hat nicht die erwartete Form</translation>
    </message>
</context>
<context>
    <name>AreaScanPlanner</name>
    <message>
        <source>The camera needs a positive sensor size, focal length and image size.</source>
        <translation>Die Kamera braucht eine positive Sensorgröße, Brennweite und Bildgröße.</translation>
    </message>
    <message>
        <source>Overlaps must be between 0 and 95 %.</source>
        <translation>Die Überlappungen müssen zwischen 0 und 95 % liegen.</translation>
    </message>
    <message>
        <source>The scan altitude (or ground sample distance) must be positive.</source>
        <translation>Die Scanhöhe (oder Bodenauflösung) muss positiv sein.</translation>
    </message>
    <message>
        <source>The turnaround distance must not be negative.</source>
        <translation>Die Wendestrecke darf nicht negativ sein.</translation>
    </message>
</context>
<context>
    <name>AtomicFile</name>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>AutosaveDirectory</name>
    <message>
        <source>Cannot create the autosave folder %1</source>
        <translation>Der Ordner für automatische Sicherungen %1 kann nicht angelegt werden</translation>
    </message>
</context>
<context>
    <name>AutosaveRecord</name>
    <message>
        <source>the autosave holds no &quot;%1&quot; route</source>
        <translation>die automatische Sicherung enthält keine Route „%1“</translation>
    </message>
    <message>
        <source>the &quot;%1&quot; document holds %2 routes, not one</source>
        <translation>das Dokument „%1“ enthält %2 Routen statt einer</translation>
    </message>
    <message>
        <source>not a Sortie autosave (&quot;format&quot; is not &quot;sortie-autosave&quot;)</source>
        <translation>keine automatische Sicherung von Sortie („format“ ist nicht „sortie-autosave“)</translation>
    </message>
    <message>
        <source>autosave format version %1 is not one this Sortie reads (1)</source>
        <translation>Format-Version %1 der automatischen Sicherung kann diese Sortie-Version nicht lesen (1)</translation>
    </message>
    <message>
        <source>&quot;savedAt&quot; is not a date and time</source>
        <translation>„savedAt“ ist kein Datum mit Uhrzeit</translation>
    </message>
</context>
<context>
    <name>AutosaveWriter</name>
    <message>
        <source>Cannot remove %1: %2</source>
        <translation>%1 kann nicht entfernt werden: %2</translation>
    </message>
</context>
<context>
    <name>Camera</name>
    <message>
        <source>DJI Phantom 4 Pro / Phantom 4 RTK (FC6310)</source>
        <translation>DJI Phantom 4 Pro / Phantom 4 RTK (FC6310)</translation>
    </message>
    <message>
        <source>DJI Phantom 4 (FC330)</source>
        <translation>DJI Phantom 4 (FC330)</translation>
    </message>
    <message>
        <source>DJI Mavic 2 Pro (Hasselblad L1D-20c)</source>
        <translation>DJI Mavic 2 Pro (Hasselblad L1D-20c)</translation>
    </message>
    <message>
        <source>DJI Mavic 3 Enterprise (wide)</source>
        <translation>DJI Mavic 3 Enterprise (wide)</translation>
    </message>
    <message>
        <source>DJI Zenmuse P1 24 mm</source>
        <translation>DJI Zenmuse P1 24 mm</translation>
    </message>
    <message>
        <source>DJI Zenmuse P1 35 mm</source>
        <translation>DJI Zenmuse P1 35 mm</translation>
    </message>
    <message>
        <source>Sony RX1R II</source>
        <translation>Sony RX1R II</translation>
    </message>
    <message>
        <source>senseFly S.O.D.A.</source>
        <translation>senseFly S.O.D.A.</translation>
    </message>
    <message>
        <source>MicaSense RedEdge-MX</source>
        <translation>MicaSense RedEdge-MX</translation>
    </message>
    <message>
        <source>GoPro Hero3 Black Edition</source>
        <translation>GoPro Hero3 Black Edition</translation>
    </message>
    <message>
        <source>Generic 1&quot; 20 MP</source>
        <translation>Generic 1&quot; 20 MP</translation>
    </message>
</context>
<context>
    <name>CertificateFingerprint</name>
    <message>
        <source>%1: %2 holds no PEM certificate</source>
        <translation>%1: %2 enthält kein PEM-Zertifikat</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is neither a SHA-256 fingerprint (64 hex digits) nor a certificate file</source>
        <translation>%1: „%2“ ist weder ein SHA-256-Fingerabdruck (64 Hexadezimalziffern) noch eine Zertifikatsdatei</translation>
    </message>
</context>
<context>
    <name>Checklist</name>
    <message>
        <source>unknown key &quot;%1&quot;</source>
        <translation>unbekannter Schlüssel „%1“</translation>
    </message>
    <message>
        <source>an item the operator ticks has no &quot;check&quot;; leave it out</source>
        <translation>ein abzuhakender Punkt hat kein „check“; lassen Sie es weg</translation>
    </message>
    <message>
        <source>an item to tick needs a &quot;title&quot;</source>
        <translation>ein abzuhakender Punkt braucht einen „title“</translation>
    </message>
    <message>
        <source>&quot;%1&quot; takes no minimum</source>
        <translation>„%1“ hat kein Minimum</translation>
    </message>
    <message>
        <source>%1 is outside %2..%3</source>
        <translation>%1 liegt außerhalb von %2..%3</translation>
    </message>
    <message>
        <source>&quot;%1&quot; needs a &quot;minimum&quot;</source>
        <translation>„%1“ braucht ein „minimum“</translation>
    </message>
    <message>
        <source>an empty list holds nothing back; say &quot;required&quot;: false instead</source>
        <translation>eine leere Liste hält nichts zurück; schreiben Sie stattdessen &quot;required&quot;: false</translation>
    </message>
    <message>
        <source>Sortie&apos;s default checklist</source>
        <translation>Sorties Standard-Checkliste</translation>
    </message>
    <message>
        <source>Propellers fitted and tight</source>
        <translation>Propeller montiert und fest</translation>
    </message>
    <message>
        <source>Take-off area clear of people</source>
        <translation>Startbereich frei von Personen</translation>
    </message>
    <message>
        <source>Payload and battery secured</source>
        <translation>Nutzlast und Akku gesichert</translation>
    </message>
    <message>
        <source>a checklist needs at least one item</source>
        <translation>eine Checkliste braucht mindestens einen Punkt</translation>
    </message>
</context>
<context>
    <name>ChecklistPanel</name>
    <message>
        <source>Pre-flight checklist</source>
        <translation>Vorflug-Checkliste</translation>
    </message>
    <message>
        <source>Ready to arm and fly the mission</source>
        <translation>Bereit zum Scharfschalten und für die Mission</translation>
    </message>
    <message>
        <source>Ready to arm; Auto waits</source>
        <translation>Bereit zum Scharfschalten; Auto wartet</translation>
    </message>
    <message>
        <source>Not ready to arm: %1 of %2 pass</source>
        <translation>Nicht bereit zum Scharfschalten: %1 von %2 erfüllt</translation>
    </message>
    <message>
        <source>Not used, Sortie&apos;s default instead: %1</source>
        <translation>Nicht verwendet, stattdessen Sorties Standard: %1</translation>
    </message>
    <message>
        <source>Sortie&apos;s default; write your own in %1</source>
        <translation>Sorties Standard; eine eigene schreiben Sie in %1</translation>
    </message>
    <message>
        <source>Choose a vehicle to see its checklist.</source>
        <translation>Wählen Sie ein Fahrzeug, um seine Checkliste zu sehen.</translation>
    </message>
    <message>
        <source>%1 (advisory)</source>
        <translation>%1 (Hinweis)</translation>
    </message>
    <message>
        <source>Read again</source>
        <translation>Neu einlesen</translation>
    </message>
    <message>
        <source>Read the checklist files again after editing them (the ticks are cleared)</source>
        <translation>Die Checklisten-Dateien nach dem Bearbeiten neu einlesen (die Haken werden gelöscht)</translation>
    </message>
</context>
<context>
    <name>CommandBar</name>
    <message>
        <source>Are you sure?</source>
        <translation>Sind Sie sicher?</translation>
    </message>
    <message numerus="yes">
        <source>To %n ticked vehicle(s): %1</source>
        <translation>
            <numerusform>An %n markiertes Fahrzeug: %1</numerusform>
            <numerusform>An %n markierte Fahrzeuge: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Untick all</source>
        <translation>Markierungen aufheben</translation>
    </message>
    <message>
        <source>Arm</source>
        <translation>Scharf schalten</translation>
    </message>
    <message>
        <source>Disarm</source>
        <translation>Entschärfen</translation>
    </message>
    <message>
        <source>Take off</source>
        <translation>Starten</translation>
    </message>
    <message>
        <source>Climb to %1 m above home</source>
        <translation>Auf %1 m über dem Home-Punkt steigen</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>Fly the uploaded mission</source>
        <translation>Die hochgeladene Mission fliegen</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <source>Land</source>
        <translation>Landen</translation>
    </message>
    <message>
        <source>Return home</source>
        <translation>Rückkehr</translation>
    </message>
    <message>
        <source>Go here…</source>
        <translation>Hierhin fliegen…</translation>
    </message>
    <message>
        <source>Then click on the map where the vehicle should fly</source>
        <translation>Dann auf der Karte klicken, wohin das Fahrzeug fliegen soll</translation>
    </message>
    <message>
        <source>Choose a vehicle on the map or in the list; tick several to command them together.</source>
        <translation>Wählen Sie ein Fahrzeug auf der Karte oder in der Liste; markieren Sie mehrere, um sie gemeinsam zu steuern.</translation>
    </message>
    <message>
        <source>The checklist does not pass</source>
        <translation>Die Checkliste ist nicht erfüllt</translation>
    </message>
    <message>
        <source>%1 is held back on %2 by:</source>
        <translation>%1 wird bei %2 zurückgehalten durch:</translation>
    </message>
    <message>
        <source>Send it anyway? The override and these reasons go into the command log and the flight log.</source>
        <translation>Trotzdem senden? Die Übergehung und diese Gründe kommen ins Befehlsprotokoll und ins Flugprotokoll.</translation>
    </message>
    <message>
        <source>Send anyway</source>
        <translation>Trotzdem senden</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Checklist ✓</source>
        <translation>Checkliste ✓</translation>
    </message>
    <message numerus="yes">
        <source>Checklist: %n to do</source>
        <translation>
            <numerusform>Checkliste: %n offen</numerusform>
            <numerusform>Checkliste: %n offen</numerusform>
        </translation>
    </message>
    <message>
        <source>The pre-flight checklist: Arm and Auto wait for its required items</source>
        <translation>Die Vorflug-Checkliste: Scharfschalten und Auto warten auf ihre Pflichtpunkte</translation>
    </message>
    <message>
        <source>Gamepad</source>
        <translation>Gamepad</translation>
    </message>
    <message>
        <source>Gamepad buttons as commands, each asking first (by default Start arms, X pauses, Y lands, B returns home). %1</source>
        <translation>Gamepad-Tasten als Befehle, jeder fragt zuerst (standardmäßig: Start schaltet scharf, X pausiert, Y landet, B kehrt heim). %1</translation>
    </message>
</context>
<context>
    <name>CommandLogView</name>
    <message>
        <source>Command log</source>
        <translation>Befehlsprotokoll</translation>
    </message>
</context>
<context>
    <name>ComparisonPanel</name>
    <message>
        <source>Compare with a route</source>
        <translation>Mit einer Route vergleichen</translation>
    </message>
    <message>
        <source>Routes (*.sortie *.plan *.waypoints *.wpl *.txt)</source>
        <translation>Routen (*.sortie *.plan *.waypoints *.wpl *.txt)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Compare with route…</source>
        <translation>Mit Route vergleichen…</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>leg</source>
        <translation>Teilstrecke</translation>
    </message>
    <message>
        <source>samples</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <source>cross-track max</source>
        <translation>Querablage max</translation>
    </message>
    <message>
        <source>mean</source>
        <translation>Mittel</translation>
    </message>
    <message>
        <source>altitude max</source>
        <translation>Höhe max</translation>
    </message>
    <message>
        <source>reached</source>
        <translation>erreicht</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
</context>
<context>
    <name>Coverage</name>
    <message>
        <source>the camera %1 has no sensor size, focal length or resolution</source>
        <translation>die Kamera %1 hat keine Sensorgröße, Brennweite oder Auflösung</translation>
    </message>
    <message>
        <source>the minimum number of images and the cell must be positive</source>
        <translation>die Mindestzahl der Bilder und die Zelle müssen positiv sein</translation>
    </message>
    <message>
        <source>its position is not a place</source>
        <translation>seine Position ist kein Ort</translation>
    </message>
    <message>
        <source>its height above the ground is not known</source>
        <translation>seine Höhe über dem Boden ist nicht bekannt</translation>
    </message>
    <message>
        <source>taken %1 m above the ground: on the ground, not surveying</source>
        <translation>aufgenommen %1 m über dem Boden: am Boden, nicht bei der Vermessung</translation>
    </message>
    <message>
        <source>its heading is not known</source>
        <translation>seine Ausrichtung ist nicht bekannt</translation>
    </message>
    <message>
        <source>no photo has a position, a height above the ground and a heading</source>
        <translation>kein Foto hat eine Position, eine Höhe über dem Boden und eine Ausrichtung</translation>
    </message>
    <message>
        <source>PROJ does not know EPSG:%1 (is proj-data installed?)</source>
        <translation>PROJ kennt EPSG:%1 nicht (ist proj-data installiert?)</translation>
    </message>
    <message>
        <source>no transformation between WGS-84 and EPSG:%1</source>
        <translation>keine Transformation zwischen WGS-84 und EPSG:%1</translation>
    </message>
    <message>
        <source>it cannot be placed in EPSG:%1</source>
        <translation>es kann nicht in EPSG:%1 verortet werden</translation>
    </message>
    <message>
        <source>no photo could be placed in EPSG:%1</source>
        <translation>kein Foto konnte in EPSG:%1 verortet werden</translation>
    </message>
    <message>
        <source>the photos span %1 × %2 m: %3 m cells would make %4 million, more than the %5 million a raster may hold; choose a larger cell</source>
        <translation>die Fotos überspannen %1 × %2 m: Zellen von %3 m ergäben %4 Millionen, mehr als die %5 Millionen, die ein Raster fassen darf; wählen Sie eine größere Zelle</translation>
    </message>
    <message>
        <source>GDAL cannot make a %1 × %2 raster in memory</source>
        <translation>GDAL kann kein Raster von %1 × %2 im Speicher anlegen</translation>
    </message>
    <message>
        <source>GDAL cannot rasterise the footprints</source>
        <translation>GDAL kann die Bildabdrücke nicht rastern</translation>
    </message>
    <message>
        <source>the photos cover no area</source>
        <translation>die Fotos decken keine Fläche ab</translation>
    </message>
    <message>
        <source>GDAL cannot rasterise the surveyed area</source>
        <translation>GDAL kann das vermessene Gebiet nicht rastern</translation>
    </message>
    <message>
        <source>GDAL cannot read its raster back</source>
        <translation>GDAL kann sein Raster nicht zurücklesen</translation>
    </message>
    <message>
        <source>GDAL cannot make the holes&apos; layer</source>
        <translation>GDAL kann die Ebene der Lücken nicht anlegen</translation>
    </message>
    <message>
        <source>GDAL cannot trace the holes</source>
        <translation>GDAL kann die Lücken nicht nachzeichnen</translation>
    </message>
    <message>
        <source>no raster to write</source>
        <translation>kein Raster zum Schreiben</translation>
    </message>
    <message>
        <source>GDAL has no GeoTIFF driver</source>
        <translation>GDAL hat keinen GeoTIFF-Treiber</translation>
    </message>
    <message>
        <source>%1 cannot be written</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>%1 cannot be put in place</source>
        <translation>%1 kann nicht an seinen Platz gelegt werden</translation>
    </message>
    <message>
        <source>Re-fly the gaps</source>
        <translation>Lücken nachfliegen</translation>
    </message>
    <message>
        <source>The hole of %1 m² at %2, %3 is not in the route: %4</source>
        <translation>Die Lücke von %1 m² bei %2, %3 ist nicht in der Route: %4</translation>
    </message>
</context>
<context>
    <name>CoverageSweep</name>
    <message>
        <source>An area scan needs a polygon of at least 3 vertices.</source>
        <translation>Ein Flächenscan braucht ein Polygon mit mindestens 3 Eckpunkten.</translation>
    </message>
    <message>
        <source>Polygon vertex %1 is not a valid position.</source>
        <translation>Polygon-Eckpunkt %1 ist keine gültige Position.</translation>
    </message>
    <message>
        <source>The polygon spans more than 100 km; split it into smaller scans.</source>
        <translation>Das Polygon ist größer als 100 km; teilen Sie es in kleinere Scans auf.</translation>
    </message>
    <message>
        <source>The scan polygon crosses itself (edges %1 and %2).</source>
        <translation>Das Scan-Polygon schneidet sich selbst (Kanten %1 und %2).</translation>
    </message>
    <message>
        <source>The scan polygon has no area.</source>
        <translation>Das Scan-Polygon hat keine Fläche.</translation>
    </message>
    <message>
        <source>The distance between passes must be positive.</source>
        <translation>Der Bahnabstand muss positiv sein.</translation>
    </message>
    <message>
        <source>The scan would need %1 transects; raise the altitude or lower the side overlap.</source>
        <translation>Der Scan bräuchte %1 Bahnen; erhöhen Sie die Höhe oder verringern Sie die Querüberlappung.</translation>
    </message>
    <message>
        <source>The scan yields no transects: the polygon is too narrow.</source>
        <translation>Der Scan ergibt keine Bahnen: Das Polygon ist zu schmal.</translation>
    </message>
</context>
<context>
    <name>CustomZoneFile</name>
    <message>
        <source>drawn on the map</source>
        <translation>auf der Karte gezeichnet</translation>
    </message>
</context>
<context>
    <name>DemFolderSource</name>
    <message>
        <source>DEM folder (%1)</source>
        <translation>DGM-Ordner (%1)</translation>
    </message>
</context>
<context>
    <name>DemOpener</name>
    <message>
        <source>%1: no such file or folder</source>
        <translation>%1: keine solche Datei und kein solcher Ordner</translation>
    </message>
</context>
<context>
    <name>DemRaster</name>
    <message>
        <source>the raster is not georeferenced (no geotransform)</source>
        <translation>das Raster ist nicht georeferenziert (keine Geotransformation)</translation>
    </message>
    <message>
        <source>the raster states no coordinate reference system</source>
        <translation>das Raster nennt kein Koordinatenreferenzsystem</translation>
    </message>
    <message>
        <source>no transformation from WGS-84 into the raster&apos;s CRS: %1</source>
        <translation>keine Transformation von WGS-84 in das KBS des Rasters: %1</translation>
    </message>
    <message>
        <source>PROJ gave no reason</source>
        <translation>PROJ nannte keinen Grund</translation>
    </message>
    <message>
        <source>the raster&apos;s extent cannot be expressed in WGS-84 degrees</source>
        <translation>die Ausdehnung des Rasters lässt sich nicht in WGS-84-Grad angeben</translation>
    </message>
    <message>
        <source>its heights are ellipsoidal and converting them to AMSL needs the EGM96 geoid: %1</source>
        <translation>seine Höhen sind ellipsoidisch, und die Umrechnung in AMSL braucht das EGM96-Geoid: %1</translation>
    </message>
</context>
<context>
    <name>Egm96Geoid</name>
    <message>
        <source>the EGM96 geoid grid %1 is missing (Debian: install proj-data): ellipsoidal heights cannot be converted to AMSL</source>
        <translation>das EGM96-Geoid-Gitter %1 fehlt (Debian: proj-data installieren): Ellipsoidische Höhen können nicht in AMSL umgerechnet werden</translation>
    </message>
    <message>
        <source>the EGM96 geoid grid %1 cannot be used: %2</source>
        <translation>das EGM96-Geoid-Gitter %1 kann nicht verwendet werden: %2</translation>
    </message>
</context>
<context>
    <name>ElevationProfileView</name>
    <message>
        <source>%1 km</source>
        <translation>%1 km</translation>
    </message>
</context>
<context>
    <name>EnduranceAdvisory</name>
    <message>
        <source>%1 Wh</source>
        <translation>%1 Wh</translation>
    </message>
</context>
<context>
    <name>EnergyProfile</name>
    <message>
        <source>%1 must be a positive number</source>
        <translation>%1 muss eine positive Zahl sein</translation>
    </message>
    <message>
        <source>reserve must be a fraction from 0 up to (not including) 1</source>
        <translation>reserve muss ein Anteil von 0 bis (ausschließlich) 1 sein</translation>
    </message>
    <message>
        <source>acceleration must be a positive number</source>
        <translation>acceleration muss eine positive Zahl sein</translation>
    </message>
    <message>
        <source>expected &quot;file&quot;, &quot;server&quot; or &quot;fit&quot;</source>
        <translation>„file“, „server“ oder „fit“ erwartet</translation>
    </message>
</context>
<context>
    <name>FleetRoutesList</name>
    <message>
        <source>Routes</source>
        <translation>Routen</translation>
    </message>
    <message>
        <source>%1 flight</source>
        <translation>%1 Flug</translation>
    </message>
    <message>
        <source>%1 flight · %2 flown · %3 left</source>
        <translation>%1 Flug · %2 geflogen · %3 verbleibend</translation>
    </message>
</context>
<context>
    <name>FlightLogExport</name>
    <message>
        <source>Flight log %1</source>
        <translation>Flugprotokoll %1</translation>
    </message>
</context>
<context>
    <name>FlightLogInfo</name>
    <message>
        <source>
  %1 (%2%3%4): %5 samples</source>
        <translation>
  %1 (%2%3%4): %5 Punkte</translation>
    </message>
</context>
<context>
    <name>FlightLogSettingsDialog</name>
    <message>
        <source>Flight logs</source>
        <translation>Flugprotokolle</translation>
    </message>
    <message>
        <source>Folder</source>
        <translation>Ordner</translation>
    </message>
    <message>
        <source>Holds</source>
        <translation>Enthält</translation>
    </message>
    <message>
        <source>Recording to</source>
        <translation>Aufzeichnung in</translation>
    </message>
    <message>
        <source>not recording</source>
        <translation>keine Aufzeichnung</translation>
    </message>
    <message>
        <source>A log up to (MB)</source>
        <translation>Ein Protokoll bis (MB)</translation>
    </message>
    <message>
        <source>The folder up to (MB)</source>
        <translation>Der Ordner bis (MB)</translation>
    </message>
    <message>
        <source>0: no limit. A log over its size continues in a new part; beyond the folder&apos;s size the oldest logs are deleted, never the one being written.</source>
        <translation>0: keine Grenze. Ein Protokoll über seiner Größe wird in einem neuen Teil fortgesetzt; über der Ordnergröße werden die ältesten Protokolle gelöscht, nie das gerade geschriebene.</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Übernehmen</translation>
    </message>
</context>
<context>
    <name>GdalDataset</name>
    <message>
        <source>no such file</source>
        <translation>keine solche Datei</translation>
    </message>
    <message>
        <source>GDAL knows no raster format for this file</source>
        <translation>GDAL kennt kein Rasterformat für diese Datei</translation>
    </message>
    <message>
        <source>the file has no raster band</source>
        <translation>die Datei hat kein Rasterband</translation>
    </message>
    <message>
        <source>GeoTIFF (COG), SRTM .hgt, DTED, ESRI ASCII grid, ERDAS Imagine, ESRI .bil/.flt, USGS DEM, PNG, JPEG, JPEG 2000 and .vrt mosaics of them</source>
        <translation>GeoTIFF (COG), SRTM .hgt, DTED, ESRI-ASCII-Raster, ERDAS Imagine, ESRI .bil/.flt, USGS DEM, PNG, JPEG, JPEG 2000 und .vrt-Mosaike daraus</translation>
    </message>
    <message>
        <source>a GDAL VRT (driver VRT) under a name that is not .vrt: Sortie reads %1</source>
        <translation>ein GDAL-VRT (Treiber VRT) unter einem Namen, der nicht auf .vrt endet: Sortie liest %1</translation>
    </message>
    <message>
        <source>GDAL reads this file with its %1 driver, which Sortie does not use for the operator&apos;s rasters: it reads %2</source>
        <translation>GDAL liest diese Datei mit seinem Treiber %1, den Sortie für die Raster des Bedieners nicht verwendet: es liest %2</translation>
    </message>
    <message>
        <source>its overview file %1 is not a GeoTIFF (GDAL: %2)</source>
        <translation>seine Übersichtsdatei %1 ist kein GeoTIFF (GDAL: %2)</translation>
    </message>
    <message>
        <source>a raw band (VRTRawRasterBand) is not read</source>
        <translation>ein Rohkanal (VRTRawRasterBand) wird nicht gelesen</translation>
    </message>
    <message>
        <source>a pixel function&apos;s code is not run</source>
        <translation>der Code einer Pixelfunktion wird nicht ausgeführt</translation>
    </message>
    <message>
        <source>its source %1 is not a local file</source>
        <translation>seine Quelle %1 ist keine lokale Datei</translation>
    </message>
    <message>
        <source>VRTs nested more than %1 deep</source>
        <translation>VRTs mehr als %1 Ebenen tief verschachtelt</translation>
    </message>
    <message>
        <source>%1: a VRT of more than %2 MiB</source>
        <translation>%1: ein VRT von mehr als %2 MiB</translation>
    </message>
    <message>
        <source>the VRT is not XML</source>
        <translation>das VRT ist kein XML</translation>
    </message>
    <message>
        <source>network access is off: Sortie reads local files only (%1)</source>
        <translation>Netzwerkzugriff ist aus: Sortie liest nur lokale Dateien (%1)</translation>
    </message>
</context>
<context>
    <name>GdalDemSource</name>
    <message>
        <source>DEM (%1)</source>
        <translation>DGM (%1)</translation>
    </message>
</context>
<context>
    <name>GeoZone</name>
    <message>
        <source>daily</source>
        <translation>täglich</translation>
    </message>
    <message>
        <source>always</source>
        <translation>immer</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <source>from %1</source>
        <translation>ab %1</translation>
    </message>
    <message>
        <source>until %1</source>
        <translation>bis %1</translation>
    </message>
    <message>
        <source>ask %1 before</source>
        <translation>%1 vorher anfragen</translation>
    </message>
    <message>
        <source>Prohibited</source>
        <translation>Verboten</translation>
    </message>
    <message>
        <source>Authorisation needed</source>
        <translation>Genehmigung nötig</translation>
    </message>
    <message>
        <source>Conditions apply</source>
        <translation>Mit Auflagen</translation>
    </message>
    <message>
        <source>Information only</source>
        <translation>Nur Information</translation>
    </message>
</context>
<context>
    <name>Geotag</name>
    <message>
        <source>the track holds no positions</source>
        <translation>der Track enthält keine Positionen</translation>
    </message>
    <message>
        <source>taken at %1, %2 s before the track starts (%3)</source>
        <translation>aufgenommen um %1, %2 s vor dem Beginn des Tracks (%3)</translation>
    </message>
    <message>
        <source>taken at %1, %2 s after the track ends (%3)</source>
        <translation>aufgenommen um %1, %2 s nach dem Ende des Tracks (%3)</translation>
    </message>
    <message>
        <source>taken at %1, in a gap of %2 s in the track (from %3 to %4; at most %5 s is bridged)</source>
        <translation>aufgenommen um %1, in einer Lücke von %2 s im Track (von %3 bis %4; überbrückt werden höchstens %5 s)</translation>
    </message>
    <message>
        <source>it holds no capture time (EXIF DateTimeOriginal or XMP exif:DateTimeOriginal)</source>
        <translation>es enthält keine Aufnahmezeit (EXIF DateTimeOriginal oder XMP exif:DateTimeOriginal)</translation>
    </message>
    <message>
        <source>its copy cannot be made in %1: %2</source>
        <translation>seine Kopie kann in %1 nicht angelegt werden: %2</translation>
    </message>
    <message>
        <source>its copy cannot be put in place: %1</source>
        <translation>seine Kopie kann nicht an ihren Platz gelegt werden: %1</translation>
    </message>
    <message>
        <source>%1 is not a folder of photos that can be read</source>
        <translation>%1 ist kein lesbarer Ordner mit Fotos</translation>
    </message>
    <message>
        <source>%1 holds no photos (.jpg, .jpeg, .tif, .tiff, .dng)</source>
        <translation>%1 enthält keine Fotos (.jpg, .jpeg, .tif, .tiff, .dng)</translation>
    </message>
    <message>
        <source>no folder given for the geotagged copies</source>
        <translation>kein Ordner für die georeferenzierten Kopien angegeben</translation>
    </message>
    <message>
        <source>%1: the folder for the geotagged copies cannot be made</source>
        <translation>%1: der Ordner für die georeferenzierten Kopien kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>%1 is the photos&apos; own folder: the copies go elsewhere, the originals are never changed</source>
        <translation>%1 ist der Ordner der Fotos selbst: die Kopien gehören woandershin, die Originale werden nie verändert</translation>
    </message>
    <message>
        <source>exiv2 cannot read it (%1)</source>
        <translation>exiv2 kann es nicht lesen (%1)</translation>
    </message>
    <message>
        <source>exiv2 cannot open it</source>
        <translation>exiv2 kann es nicht öffnen</translation>
    </message>
    <message>
        <source>its OffsetTimeOriginal &quot;%1&quot; is no time zone offset (±HH:MM)</source>
        <translation>sein OffsetTimeOriginal „%1“ ist kein Zeitzonenversatz (±HH:MM)</translation>
    </message>
    <message>
        <source>no valid position to write</source>
        <translation>keine gültige Position zum Schreiben</translation>
    </message>
    <message>
        <source>exiv2 cannot write its tags (%1)</source>
        <translation>exiv2 kann seine Tags nicht schreiben (%1)</translation>
    </message>
    <message>
        <source>%1 is not a GPX file (its root element is &lt;%2&gt;, not &lt;gpx&gt;)</source>
        <translation>%1 ist keine GPX-Datei (ihr Wurzelelement ist &lt;%2&gt;, nicht &lt;gpx&gt;)</translation>
    </message>
    <message>
        <source>%1: a track point needs lat (-90 to 90) and lon (-180 to 180) in degrees, not lat=&quot;%2&quot; lon=&quot;%3&quot;</source>
        <translation>%1: ein Trackpunkt braucht lat (-90 bis 90) und lon (-180 bis 180) in Grad, nicht lat=&quot;%2&quot; lon=&quot;%3&quot;</translation>
    </message>
    <message>
        <source>%1: &lt;ele&gt; &quot;%2&quot; is no elevation in metres</source>
        <translation>%1: &lt;ele&gt; „%2“ ist keine Höhe in Metern</translation>
    </message>
    <message>
        <source>%1: &lt;time&gt; &quot;%2&quot; is no UTC time (YYYY-MM-DDThh:mm:ssZ)</source>
        <translation>%1: &lt;time&gt; „%2“ ist keine UTC-Zeit (YYYY-MM-DDThh:mm:ssZ)</translation>
    </message>
    <message>
        <source>%1: the track point has no &lt;time&gt;, so no photo can be matched to it</source>
        <translation>%1: der Trackpunkt hat kein &lt;time&gt;, daher kann ihm kein Foto zugeordnet werden</translation>
    </message>
    <message>
        <source>%1 is not a readable GPX file: %2</source>
        <translation>%1 ist keine lesbare GPX-Datei: %2</translation>
    </message>
    <message>
        <source>%1 is not a GPX file (no &lt;gpx&gt; element)</source>
        <translation>%1 ist keine GPX-Datei (kein &lt;gpx&gt;-Element)</translation>
    </message>
    <message>
        <source>%1 holds no track points (&lt;trkpt&gt;)</source>
        <translation>%1 enthält keine Trackpunkte (&lt;trkpt&gt;)</translation>
    </message>
    <message>
        <source>%1 has no such vehicle</source>
        <translation>%1 enthält dieses Fahrzeug nicht</translation>
    </message>
    <message>
        <source>%1: vehicle %2 reported no position</source>
        <translation>%1: Fahrzeug %2 hat keine Position gemeldet</translation>
    </message>
    <message>
        <source>exiv2 wrote its tags but they do not read back</source>
        <translation>exiv2 hat die Tags geschrieben, liest sie aber nicht zurück</translation>
    </message>
    <message>
        <source>exiv2 wrote a copy it cannot read back (%1)</source>
        <translation>exiv2 hat eine Kopie geschrieben, die es nicht zurücklesen kann (%1)</translation>
    </message>
    <message>
        <source>no photo the vehicle reported taking matches its time (a shot before or after the flight, or another camera&apos;s)</source>
        <translation>kein vom Fahrzeug gemeldetes Foto passt zu seiner Zeit (eine Aufnahme vor oder nach dem Flug oder von einer anderen Kamera)</translation>
    </message>
</context>
<context>
    <name>GlanceBar</name>
    <message>
        <source>The connection to the server</source>
        <translation>Die Verbindung zum Server</translation>
    </message>
    <message>
        <source>The vehicle chosen in the fly view, else the first</source>
        <translation>Das in der Flugansicht gewählte Fahrzeug, sonst das erste</translation>
    </message>
    <message>
        <source>Its GPS: the fix and the satellites in view</source>
        <translation>Sein GPS: die Positionsbestimmung und die sichtbaren Satelliten</translation>
    </message>
    <message>
        <source>Its battery, against the low and critical levels</source>
        <translation>Sein Akku, gemessen an der niedrigen und der kritischen Schwelle</translation>
    </message>
    <message>
        <source>Its link: how often its position arrives</source>
        <translation>Seine Verbindung: wie oft seine Position ankommt</translation>
    </message>
</context>
<context>
    <name>HciConnection</name>
    <message>
        <source>type %1</source>
        <translation>Typ %1</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>No answer from %1 within %2: check the address and the network</source>
        <translation>Keine Antwort von %1 innerhalb von %2: Prüfen Sie die Adresse und das Netzwerk</translation>
    </message>
    <message>
        <source>The server at %1 closed the connection</source>
        <translation>Der Server bei %1 hat die Verbindung geschlossen</translation>
    </message>
    <message>
        <source>The connection was closed by the application</source>
        <translation>Die Verbindung wurde von der Anwendung geschlossen</translation>
    </message>
    <message>
        <source>Disconnected from %1</source>
        <translation>Verbindung zu %1 getrennt</translation>
    </message>
    <message>
        <source>%1 refused the connection</source>
        <translation>%1 hat die Verbindung abgelehnt</translation>
    </message>
    <message>
        <source>The host in %1 cannot be found</source>
        <translation>Der Host in %1 wurde nicht gefunden</translation>
    </message>
    <message>
        <source>Cannot reach %1: %2</source>
        <translation>%1 nicht erreichbar: %2</translation>
    </message>
    <message>
        <source>Connection to %1 lost: %2</source>
        <translation>Verbindung zu %1 verloren: %2</translation>
    </message>
    <message>
        <source>%1 got no answer: %2</source>
        <translation>%1 hat keine Antwort erhalten: %2</translation>
    </message>
    <message>
        <source>%1 is not an HCI message</source>
        <translation>%1 ist keine HCI-Nachricht</translation>
    </message>
    <message>
        <source>%1 not sent: not connected to the server</source>
        <translation>%1 nicht gesendet: keine Verbindung zum Server</translation>
    </message>
    <message>
        <source>%1 not sent: missing %2</source>
        <translation>%1 nicht gesendet: %2 fehlt</translation>
    </message>
    <message>
        <source>No answer to %1 within %2</source>
        <translation>Keine Antwort auf %1 innerhalb von %2</translation>
    </message>
    <message>
        <source>%1 at byte %2: %3</source>
        <translation>%1 bei Byte %2: %3</translation>
    </message>
    <message>
        <source>%1 with instance id -1 is not a notification</source>
        <translation>%1 mit Instanz-ID -1 ist keine Benachrichtigung</translation>
    </message>
    <message>
        <source>%1 for instance id %2, which no request waits for (answered after its timeout?)</source>
        <translation>%1 für Instanz-ID %2, auf die keine Anfrage wartet (nach ihrer Zeitüberschreitung beantwortet?)</translation>
    </message>
    <message>
        <source>The server answered %1 with %2 instead of %3</source>
        <translation>Der Server hat auf %1 mit %2 statt %3 geantwortet</translation>
    </message>
    <message>
        <source>Not connected to %1 over TLS: %2</source>
        <translation>Keine Verbindung zu %1 über TLS: %2</translation>
    </message>
    <message>
        <source>The TLS handshake with %1 failed (%2): does it speak TLS on that port?</source>
        <translation>Der TLS-Handshake mit %1 ist fehlgeschlagen (%2): Spricht der Server auf diesem Port TLS?</translation>
    </message>
    <message>
        <source>%1 accepted the connection but did not begin TLS within %2: is it a plain HCI server?</source>
        <translation>%1 hat die Verbindung angenommen, aber binnen %2 kein TLS begonnen: Ist es ein unverschlüsselter HCI-Server?</translation>
    </message>
</context>
<context>
    <name>HciElevationSource</name>
    <message>
        <source>UgCS server</source>
        <translation>UgCS-Server</translation>
    </message>
</context>
<context>
    <name>HciError</name>
    <message>
        <source>The server&apos;s licence does not allow this (%1)</source>
        <translation>Die Lizenz des Servers erlaubt dies nicht (%1)</translation>
    </message>
    <message>
        <source>The server&apos;s licence does not allow this</source>
        <translation>Die Lizenz des Servers erlaubt dies nicht</translation>
    </message>
    <message>
        <source>The server speaks HCI protocol %1; Sortie speaks 2.0%2</source>
        <translation>Der Server spricht HCI-Protokoll %1; Sortie spricht 2.0%2</translation>
    </message>
    <message>
        <source>The server refused the request (error %1)</source>
        <translation>Der Server hat die Anfrage abgelehnt (Fehler %1)</translation>
    </message>
    <message>
        <source>The server refused the request without a reason</source>
        <translation>Der Server hat die Anfrage ohne Begründung abgelehnt</translation>
    </message>
    <message>
        <source>no error</source>
        <translation>kein Fehler</translation>
    </message>
    <message>
        <source> (code %1)</source>
        <translation> (Code %1)</translation>
    </message>
</context>
<context>
    <name>HciRouteMapper</name>
    <message>
        <source>Route &quot;%1&quot;, segment %2: %3</source>
        <translation>Route „%1“, Segment %2: %3</translation>
    </message>
</context>
<context>
    <name>HciRoutePass</name>
    <message>
        <source>a RoutePass event names the object type &quot;%1&quot;</source>
        <translation>ein RoutePass-Ereignis nennt den Objekttyp „%1“</translation>
    </message>
    <message>
        <source>RoutePass %1: the event carries no RoutePass</source>
        <translation>RoutePass %1: Das Ereignis enthält keinen RoutePass</translation>
    </message>
    <message>
        <source>RoutePass %1 names no vehicle</source>
        <translation>RoutePass %1 nennt kein Fahrzeug</translation>
    </message>
    <message>
        <source>RoutePass %1 has no waypoint count</source>
        <translation>RoutePass %1 hat keine Wegpunktanzahl</translation>
    </message>
    <message>
        <source>RoutePass %1: waypoint index %2 is outside the route&apos;s %3 waypoints</source>
        <translation>RoutePass %1: Wegpunktindex %2 liegt außerhalb der %3 Wegpunkte der Route</translation>
    </message>
</context>
<context>
    <name>HciSegmentMapper</name>
    <message>
        <source>the waypoint has no figure point</source>
        <translation>der Wegpunkt hat keinen Figurpunkt</translation>
    </message>
    <message>
        <source>the waypoint&apos;s position is out of range</source>
        <translation>die Position des Wegpunkts liegt außerhalb des gültigen Bereichs</translation>
    </message>
    <message>
        <source>An area scan&apos;s %1: %2 It keeps Sortie&apos;s default.</source>
        <translation>Flächenscan, %1: %2 Es gilt der Standardwert von Sortie.</translation>
    </message>
    <message>
        <source>An area scan came without a camera; Sortie&apos;s default camera (%1) was assumed.</source>
        <translation>Ein Flächenscan kam ohne Kamera; die Standardkamera von Sortie (%1) wurde angenommen.</translation>
    </message>
    <message>
        <source>A %1 segment could not be read as one (%2); it is kept as the server sent it.</source>
        <translation>Ein %1-Segment konnte nicht als solches gelesen werden (%2); es bleibt so, wie der Server es gesendet hat.</translation>
    </message>
    <message>
        <source>An area scan without a polygon of three corners is kept as the server sent it.</source>
        <translation>Ein Flächenscan ohne Polygon mit drei Ecken bleibt so, wie der Server ihn gesendet hat.</translation>
    </message>
</context>
<context>
    <name>HciSession</name>
    <message>
        <source> not sent: </source>
        <translation> nicht gesendet: </translation>
    </message>
    <message>
        <source>the connection to the server is being re-established</source>
        <translation>die Verbindung zum Server wird wiederhergestellt</translation>
    </message>
    <message>
        <source>not logged in to a server</source>
        <translation>nicht an einem Server angemeldet</translation>
    </message>
    <message>
        <source>The server sent nothing while %1 waited (%2); the link seems dead</source>
        <translation>Der Server hat nichts gesendet, während %1 wartete (%2); die Verbindung scheint abgerissen</translation>
    </message>
    <message>
        <source>The server speaks HCI protocol %1.%2; Sortie speaks %3.%4</source>
        <translation>Der Server spricht HCI-Protokoll %1.%2; Sortie spricht %3.%4</translation>
    </message>
    <message>
        <source>The server rejected the login &apos;%1&apos;: %2</source>
        <translation>Der Server hat die Anmeldung „%1“ abgelehnt: %2</translation>
    </message>
</context>
<context>
    <name>HciVehicleLink</name>
    <message>
        <source>%1: cannot take control of %2: %3</source>
        <translation>%1: Kontrolle über %2 kann nicht übernommen werden: %3</translation>
    </message>
    <message>
        <source>%1: the server sent no result for this vehicle</source>
        <translation>%1: Der Server hat für dieses Fahrzeug kein Ergebnis gesendet</translation>
    </message>
    <message>
        <source>there is no such flight mode</source>
        <translation>diesen Flugmodus gibt es nicht</translation>
    </message>
    <message>
        <source>Segment %1: %2</source>
        <translation>Segment %1: %2</translation>
    </message>
    <message>
        <source>the server could not process it</source>
        <translation>der Server konnte es nicht verarbeiten</translation>
    </message>
    <message>
        <source>Sortie upload to %1</source>
        <translation>Sortie-Upload auf %1</translation>
    </message>
    <message>
        <source>route processing: %1</source>
        <translation>Routenverarbeitung: %1</translation>
    </message>
    <message>
        <source>upload: the mission was not prepared by the UgCS server</source>
        <translation>Upload: Die Mission wurde nicht vom UgCS-Server vorbereitet</translation>
    </message>
    <message>
        <source>upload: %1</source>
        <translation>Upload: %1</translation>
    </message>
    <message>
        <source>upload: cannot take control of %1: %2</source>
        <translation>Upload: Kontrolle über %1 kann nicht übernommen werden: %2</translation>
    </message>
    <message>
        <source>a UgCS server does not read a vehicle&apos;s mission back</source>
        <translation>ein UgCS-Server liest die Mission eines Fahrzeugs nicht zurück</translation>
    </message>
    <message>
        <source>%1: parameters are set in the vehicle profile on the UgCS server</source>
        <translation>%1: Parameter werden im Fahrzeugprofil auf dem UgCS-Server gesetzt</translation>
    </message>
</context>
<context>
    <name>HgtTile</name>
    <message>
        <source>%1 bytes is not an SRTM tile (2884802 bytes for 3″ 1201×1201, 25934402 for 1″ 3601×3601); the file is truncated or not a .hgt tile</source>
        <translation>%1 Bytes sind keine SRTM-Kachel (2884802 Bytes für 3″ 1201×1201, 25934402 für 1″ 3601×3601); die Datei ist abgeschnitten oder keine .hgt-Kachel</translation>
    </message>
    <message>
        <source>height %1 m at row %2, column %3 is not a terrain height; the file is corrupt</source>
        <translation>Höhe %1 m in Zeile %2, Spalte %3 ist keine Geländehöhe; die Datei ist beschädigt</translation>
    </message>
</context>
<context>
    <name>HgtTileSource</name>
    <message>
        <source>%1: no such file or folder</source>
        <translation>%1: Datei oder Ordner nicht vorhanden</translation>
    </message>
    <message>
        <source>%1: not an SRTM tile name (NxxEyyy.hgt names the tile&apos;s south-west corner)</source>
        <translation>%1: kein SRTM-Kachelname (NxxEyyy.hgt benennt die Südwestecke der Kachel)</translation>
    </message>
    <message>
        <source>SRTM tiles (%1)</source>
        <translation>SRTM-Kacheln (%1)</translation>
    </message>
    <message>
        <source>%1: cannot be mapped: %2</source>
        <translation>%1: kann nicht in den Speicher abgebildet werden: %2</translation>
    </message>
</context>
<context>
    <name>IndexedDemSource</name>
    <message>
        <source>%1: no rasters</source>
        <translation>%1: keine Raster</translation>
    </message>
</context>
<context>
    <name>InstrumentPanel</name>
    <message>
        <source>%1 (%2, %3)</source>
        <translation>%1 (%2, %3)</translation>
    </message>
    <message>
        <source>No vehicle chosen</source>
        <translation>Kein Fahrzeug gewählt</translation>
    </message>
    <message>
        <source>Altitude AGL</source>
        <translation>Höhe AGL</translation>
    </message>
    <message>
        <source>Altitude AMSL</source>
        <translation>Höhe AMSL</translation>
    </message>
    <message>
        <source>Ground speed</source>
        <translation>Grundgeschw.</translation>
    </message>
    <message>
        <source>Vertical speed</source>
        <translation>Steigrate</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Kurs</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Akku</translation>
    </message>
    <message>
        <source>GPS</source>
        <translation>GPS</translation>
    </message>
    <message>
        <source>fix %1, %2 satellites</source>
        <translation>Fix %1, %2 Satelliten</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <source>Armed</source>
        <translation>Scharf</translation>
    </message>
    <message>
        <source>ARMED</source>
        <translation>SCHARF</translation>
    </message>
    <message>
        <source>disarmed</source>
        <translation>entschärft</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source> (no data)</source>
        <translation> (keine Daten)</translation>
    </message>
    <message>
        <source>%1, %2 Hz</source>
        <translation>%1, %2 Hz</translation>
    </message>
    <message>
        <source>Flight time</source>
        <translation>Flugzeit</translation>
    </message>
    <message>
        <source>To home</source>
        <translation>Zum Home-Punkt</translation>
    </message>
    <message>
        <source>Mission</source>
        <translation>Mission</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Verbleibend</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
</context>
<context>
    <name>JsonCursor</name>
    <message>
        <source>expected an object, found %1</source>
        <translation>Objekt erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>missing required key &quot;%1&quot;</source>
        <translation>erforderlicher Schlüssel „%1“ fehlt</translation>
    </message>
    <message>
        <source>expected an array, found %1</source>
        <translation>Array erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>expected at least %1 elements, found %2</source>
        <translation>mindestens %1 Elemente erwartet, gefunden: %2</translation>
    </message>
    <message>
        <source>expected a number, found %1</source>
        <translation>Zahl erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>the number is not finite</source>
        <translation>die Zahl ist nicht endlich</translation>
    </message>
    <message>
        <source>expected an integer, found %1</source>
        <translation>ganze Zahl erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>expected true or false, found %1</source>
        <translation>true oder false erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>expected a string, found %1</source>
        <translation>Zeichenkette erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>not valid JSON: %1</source>
        <translation>kein gültiges JSON: %1</translation>
    </message>
    <message>
        <source>unknown value &quot;%1&quot;</source>
        <translation>unbekannter Wert „%1“</translation>
    </message>
</context>
<context>
    <name>KmlFormat</name>
    <message>
        <source>bad coordinate &quot;%1&quot;: expected longitude,latitude[,altitude]</source>
        <translation>ungültige Koordinate „%1“: Länge,Breite[,Höhe] erwartet</translation>
    </message>
    <message>
        <source>bad coordinate &quot;%1&quot;: not a number</source>
        <translation>ungültige Koordinate „%1“: keine Zahl</translation>
    </message>
    <message>
        <source>coordinate &quot;%1&quot; is out of range</source>
        <translation>Koordinate „%1“ liegt außerhalb des gültigen Bereichs</translation>
    </message>
    <message>
        <source>a boundary needs at least 3 distinct points, found %1</source>
        <translation>eine Begrenzung braucht mindestens 3 verschiedene Punkte, gefunden: %1</translation>
    </message>
    <message>
        <source>not valid KML: %1</source>
        <translation>kein gültiges KML: %1</translation>
    </message>
    <message>
        <source>this LineString is open, so it encloses no area; close it (last point = first) to use it as a boundary</source>
        <translation>dieser LineString ist offen und schließt daher keine Fläche ein; schließen Sie ihn (letzter Punkt = erster), um ihn als Begrenzung zu verwenden</translation>
    </message>
    <message>
        <source>this Placemark has no Polygon (with an outerBoundaryIs LinearRing) or closed LineString</source>
        <translation>dieses Placemark hat kein Polygon (mit einem outerBoundaryIs-LinearRing) und keinen geschlossenen LineString</translation>
    </message>
    <message>
        <source>the document has no Polygon or closed LineString</source>
        <translation>das Dokument hat kein Polygon und keinen geschlossenen LineString</translation>
    </message>
    <message>
        <source>The file holds %1 closed shapes; the one at line %2 was imported.</source>
        <translation>Die Datei enthält %1 geschlossene Formen; die in Zeile %2 wurde importiert.</translation>
    </message>
    <message>
        <source>Flight path</source>
        <translation>Flugweg</translation>
    </message>
    <message>
        <source>Flight path, part %1</source>
        <translation>Flugweg, Teil %1</translation>
    </message>
</context>
<context>
    <name>KmlZones</name>
    <message>
        <source>bad coordinate &quot;%1&quot;: expected longitude,latitude[,altitude]</source>
        <translation>ungültige Koordinate „%1“: Länge,Breite[,Höhe] erwartet</translation>
    </message>
    <message>
        <source>coordinate &quot;%1&quot; is out of range</source>
        <translation>Koordinate „%1“ liegt außerhalb des gültigen Bereichs</translation>
    </message>
    <message>
        <source>a boundary needs at least 3 distinct coordinates, found %1</source>
        <translation>eine Begrenzung braucht mindestens 3 verschiedene Koordinaten, gefunden: %1</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
    <message>
        <source>line %1: a polygon with two outer boundaries</source>
        <translation>Zeile %1: ein Polygon mit zwei äußeren Begrenzungen</translation>
    </message>
    <message>
        <source>line %1: an inner boundary before the outer one</source>
        <translation>Zeile %1: eine innere Begrenzung vor der äußeren</translation>
    </message>
    <message>
        <source>Placemark %1</source>
        <translation>Placemark %1</translation>
    </message>
    <message>
        <source>Placemark &apos;%1&apos;</source>
        <translation>Placemark „%1“</translation>
    </message>
    <message>
        <source>a Polygon without an outer boundary</source>
        <translation>ein Polygon ohne äußere Begrenzung</translation>
    </message>
    <message>
        <source>%1 (line %2) was left out: %3</source>
        <translation>%1 (Zeile %2) wurde ausgelassen: %3</translation>
    </message>
    <message>
        <source>not well-formed KML: %1</source>
        <translation>kein wohlgeformtes KML: %1</translation>
    </message>
</context>
<context>
    <name>LandOutlines</name>
    <message>
        <source>the land outline file is not compressed data</source>
        <translation>die Landumriss-Datei enthält keine komprimierten Daten</translation>
    </message>
    <message>
        <source>the land outline file does not start with %1</source>
        <translation>die Landumriss-Datei beginnt nicht mit %1</translation>
    </message>
    <message>
        <source>the land outline file is truncated at its polygon count</source>
        <translation>die Landumriss-Datei ist bei der Polygonanzahl abgeschnitten</translation>
    </message>
    <message>
        <source>the land outline file is truncated in polygon %1</source>
        <translation>die Landumriss-Datei ist in Polygon %1 abgeschnitten</translation>
    </message>
    <message>
        <source>the land outline file is truncated in polygon %1, ring %2</source>
        <translation>die Landumriss-Datei ist in Polygon %1, Ring %2 abgeschnitten</translation>
    </message>
    <message>
        <source>the built-in land outlines (%1) are missing</source>
        <translation>die eingebauten Landumrisse (%1) fehlen</translation>
    </message>
</context>
<context>
    <name>LoginPage</name>
    <message>
        <source>Connect to a UgCS server</source>
        <translation>Mit einem UgCS-Server verbinden</translation>
    </message>
    <message>
        <source>Server (host:port)</source>
        <translation>Server (Host:Port)</translation>
    </message>
    <message>
        <source>Host name or address and HCI port of the UgCS server</source>
        <translation>Hostname oder Adresse und HCI-Port des UgCS-Servers</translation>
    </message>
    <message>
        <source>User</source>
        <translation>Benutzer</translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Passwort</translation>
    </message>
    <message>
        <source>Remember the password on this computer</source>
        <translation>Passwort auf diesem Computer speichern</translation>
    </message>
    <message>
        <source>Kept in this computer&apos;s keyring for this server and user, never in a file</source>
        <translation>Wird im Schlüsselbund dieses Computers für diesen Server und Benutzer gespeichert, nie in einer Datei</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>Log in (Enter in the password field)</source>
        <translation>Anmelden (Enter im Passwortfeld)</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
    <message>
        <source>Logged in as %1 at %2.</source>
        <translation>Angemeldet als %1 bei %2.</translation>
    </message>
    <message>
        <source>%1…</source>
        <translation>%1…</translation>
    </message>
    <message>
        <source>Secure (TLS)</source>
        <translation>Sicher (TLS)</translation>
    </message>
    <message>
        <source>For a server behind a TLS terminator: the password and everything else travel encrypted</source>
        <translation>Für einen Server hinter einem TLS-Terminator: Passwort und alles andere werden verschlüsselt übertragen</translation>
    </message>
    <message>
        <source>Send in clear</source>
        <translation>Unverschlüsselt senden</translation>
    </message>
    <message>
        <source>Do not connect</source>
        <translation>Nicht verbinden</translation>
    </message>
</context>
<context>
    <name>Main</name>
    <message>
        <source>Sortie</source>
        <translation>Sortie</translation>
    </message>
    <message>
        <source>Login</source>
        <translation>Anmeldung</translation>
    </message>
    <message>
        <source>Mission</source>
        <translation>Mission</translation>
    </message>
    <message>
        <source>Live telemetry</source>
        <translation>Live-Telemetrie</translation>
    </message>
    <message>
        <source>Map…</source>
        <translation>Karte…</translation>
    </message>
    <message>
        <source>Choose the map source (Ctrl+M)</source>
        <translation>Kartenquelle wählen (Strg+M)</translation>
    </message>
    <message>
        <source>Offline…</source>
        <translation>Offline…</translation>
    </message>
    <message>
        <source>Download the web map of an area for work without a network</source>
        <translation>Die Webkarte eines Gebiets für die Arbeit ohne Netzwerk herunterladen</translation>
    </message>
    <message>
        <source>Logs…</source>
        <translation>Protokolle…</translation>
    </message>
    <message>
        <source>Where flight logs are recorded, and how much they may take</source>
        <translation>Wo Flugprotokolle aufgezeichnet werden und wie viel Platz sie belegen dürfen</translation>
    </message>
    <message>
        <source>ft, mph</source>
        <translation>ft, mph</translation>
    </message>
    <message>
        <source>m, m/s</source>
        <translation>m, m/s</translation>
    </message>
    <message>
        <source>Switch between metric and imperial units</source>
        <translation>Zwischen metrischen und imperialen Einheiten wechseln</translation>
    </message>
    <message>
        <source>Keyboard shortcuts (F1)</source>
        <translation>Tastenkürzel (F1)</translation>
    </message>
    <message>
        <source>The language of Sortie, applied at once</source>
        <translation>Sprache von Sortie, sofort wirksam</translation>
    </message>
    <message>
        <source>Display…</source>
        <translation>Anzeige…</translation>
    </message>
    <message>
        <source>Units, language and colours</source>
        <translation>Einheiten, Sprache und Farben</translation>
    </message>
    <message>
        <source>Units</source>
        <translation>Einheiten</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>Colours</source>
        <translation>Farben</translation>
    </message>
    <message>
        <source>The system&apos;s colours, light, dark, or high contrast for sunlight</source>
        <translation>Die Farben des Systems, hell, dunkel oder hoher Kontrast für Sonnenlicht</translation>
    </message>
</context>
<context>
    <name>MapPane</name>
    <message>
        <source>Zoom in (+, wheel)</source>
        <translation>Vergrößern (+, Mausrad)</translation>
    </message>
    <message>
        <source>Zoom out (−, wheel)</source>
        <translation>Verkleinern (−, Mausrad)</translation>
    </message>
</context>
<context>
    <name>MapSourceDialog</name>
    <message>
        <source>Map source</source>
        <translation>Kartenquelle</translation>
    </message>
    <message>
        <source>Offline base map (land outlines, always available)</source>
        <translation>Offline-Grundkarte (Landumrisse, immer verfügbar)</translation>
    </message>
    <message>
        <source>Web tiles from a URL template</source>
        <translation>Web-Kacheln aus einer URL-Vorlage</translation>
    </message>
    <message>
        <source>{z}, {x} and {y} (or {-y}) are replaced per tile; {s} by a subdomain</source>
        <translation>{z}, {x} und {y} (oder {-y}) werden pro Kachel ersetzt; {s} durch eine Subdomain</translation>
    </message>
    <message>
        <source>MBTiles file (offline raster tiles)</source>
        <translation>MBTiles-Datei (Offline-Rasterkacheln)</translation>
    </message>
    <message>
        <source>/path/to/area.mbtiles</source>
        <translation>/pfad/zu/gebiet.mbtiles</translation>
    </message>
    <message>
        <source>Orthophoto over the base map (GeoTIFF or any raster GDAL reads, any CRS)</source>
        <translation>Orthofoto über der Grundkarte (GeoTIFF oder jedes Raster, das GDAL liest, beliebiges Koordinatensystem)</translation>
    </message>
    <message>
        <source>/path/to/orthophoto.tif (empty: none)</source>
        <translation>/pfad/zu/orthofoto.tif (leer: keins)</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Deckkraft</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Terrain: a DEM file (GeoTIFF, .hgt, ...) or a folder of them</source>
        <translation>Gelände: eine DEM-Datei (GeoTIFF, .hgt, ...) oder ein Ordner davon</translation>
    </message>
    <message>
        <source>/path/to/dem.tif or /path/to/dem-folder (empty: none)</source>
        <translation>/pfad/zu/dem.tif oder /pfad/zu/dem-ordner (leer: keins)</translation>
    </message>
    <message>
        <source>Orthophoto</source>
        <translation>Orthofoto</translation>
    </message>
    <message>
        <source>Rasters (*.tif *.tiff *.jp2 *.vrt *.img *.ecw *.sid *.png *.jpg)</source>
        <translation>Raster (*.tif *.tiff *.jp2 *.vrt *.img *.ecw *.sid *.png *.jpg)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Terrain model (DEM)</source>
        <translation>Geländemodell (DEM)</translation>
    </message>
    <message>
        <source>Elevation rasters (*.tif *.tiff *.hgt *.vrt *.dt0 *.dt1 *.dt2 *.asc *.img *.bil *.flt *.dem)</source>
        <translation>Höhenraster (*.tif *.tiff *.hgt *.vrt *.dt0 *.dt1 *.dt2 *.asc *.img *.bil *.flt *.dem)</translation>
    </message>
    <message>
        <source>A folder of terrain models (DEM tiles)</source>
        <translation>Ein Ordner mit Geländemodellen (DEM-Kacheln)</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>File…</source>
        <translation>Datei…</translation>
    </message>
    <message>
        <source>Folder…</source>
        <translation>Ordner…</translation>
    </message>
</context>
<context>
    <name>MavlinkExport</name>
    <message>
        <source>MAVLink has no stop-and-turn or bank-turn waypoints: they were written as plain waypoints.</source>
        <translation>MAVLink kennt keine Stop-and-Turn- oder Bank-Turn-Wegpunkte: Sie wurden als einfache Wegpunkte geschrieben.</translation>
    </message>
    <message>
        <source>Waypoint %1: %2 has no MAVLink equivalent and was left out.</source>
        <translation>Wegpunkt %1: Für %2 gibt es in MAVLink keine Entsprechung; die Aktion wurde ausgelassen.</translation>
    </message>
    <message>
        <source>a servo action without its servo and PWM</source>
        <translation>eine Servo-Aktion ohne Servo und PWM</translation>
    </message>
    <message>
        <source>a repeated servo without its count and cycle time</source>
        <translation>ein wiederholtes Servo ohne Anzahl und Zykluszeit</translation>
    </message>
    <message>
        <source>waiting for the operator</source>
        <translation>das Warten auf den Bediener</translation>
    </message>
    <message>
        <source>a heading relative to the course</source>
        <translation>einen Kurs relativ zur Flugrichtung</translation>
    </message>
    <message>
        <source>toggling video</source>
        <translation>das Umschalten des Videos</translation>
    </message>
    <message>
        <source>the series&apos; start delay</source>
        <translation>die Startverzögerung der Serie</translation>
    </message>
    <message>
        <source>the series&apos; shot count and start delay</source>
        <translation>die Aufnahmeanzahl und Startverzögerung der Serie</translation>
    </message>
    <message>
        <source>a panorama</source>
        <translation>ein Panorama</translation>
    </message>
    <message>
        <source>Waypoint %1: the gimbal&apos;s %2 was not set and is written as 0° (MAVLink has no &quot;unchanged&quot;).</source>
        <translation>Wegpunkt %1: Am Gimbal ist %2 nicht gesetzt und wird als 0° geschrieben (MAVLink kennt kein „unverändert“).</translation>
    </message>
    <message>
        <source>a zoom level</source>
        <translation>eine Zoomstufe</translation>
    </message>
    <message>
        <source>%1 was left out: %2</source>
        <translation>%1 wurde ausgelassen: %2</translation>
    </message>
    <message>
        <source>it cannot be planned</source>
        <translation>es kann nicht geplant werden</translation>
    </message>
    <message>
        <source>Segments without a MAVLink equivalent (circle, perimeter...) were written as the waypoints Sortie plans for them.</source>
        <translation>Segmente ohne MAVLink-Entsprechung (Kreis, Umfangsflug...) wurden als die Wegpunkte geschrieben, die Sortie für sie plant.</translation>
    </message>
    <message>
        <source>Area scan %1 was left out: %2</source>
        <translation>Flächenscan %1 wurde ausgelassen: %2</translation>
    </message>
    <message>
        <source>Area scan %1 was written as %2 waypoints with distance triggering.</source>
        <translation>Flächenscan %1 wurde als %2 Wegpunkte mit streckenabhängiger Auslösung geschrieben.</translation>
    </message>
    <message>
        <source>tilt</source>
        <extracomment>A gimbal&apos;s axis, listed in &quot;the gimbal&apos;s %2 was not set&quot; (tilt, roll, yaw).</extracomment>
        <translation>Neigung</translation>
    </message>
    <message>
        <source>roll</source>
        <extracomment>A gimbal&apos;s axis, listed in &quot;the gimbal&apos;s %2 was not set&quot; (tilt, roll, yaw).</extracomment>
        <translation>Rollachse</translation>
    </message>
    <message>
        <source>yaw</source>
        <extracomment>A gimbal&apos;s axis, listed in &quot;the gimbal&apos;s %2 was not set&quot; (tilt, roll, yaw).</extracomment>
        <translation>Gierachse</translation>
    </message>
</context>
<context>
    <name>MbTilesFile</name>
    <message>
        <source>No MBTiles file is set.</source>
        <translation>Keine MBTiles-Datei festgelegt.</translation>
    </message>
    <message>
        <source>The MBTiles file %1 does not exist.</source>
        <translation>Die MBTiles-Datei %1 existiert nicht.</translation>
    </message>
    <message>
        <source>Cannot open the MBTiles file %1: %2</source>
        <translation>Die MBTiles-Datei %1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>%1 is not an MBTiles file Sortie can write: %2</source>
        <translation>%1 ist keine MBTiles-Datei, die Sortie schreiben kann: %2</translation>
    </message>
    <message>
        <source>%1 is not an MBTiles file (it has no tiles table).</source>
        <translation>%1 ist keine MBTiles-Datei (sie hat keine Tabelle „tiles“).</translation>
    </message>
    <message>
        <source>The MBTiles file %1 has no readable metadata: %2</source>
        <translation>Die MBTiles-Datei %1 hat keine lesbaren Metadaten: %2</translation>
    </message>
    <message>
        <source>Cannot write to the MBTiles file %1: %2</source>
        <translation>In die MBTiles-Datei %1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>Cannot write the metadata of %1: %2</source>
        <translation>Die Metadaten von %1 können nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>Reading tile %1 failed: %2</source>
        <translation>Lesen der Kachel %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>Writing %1 tiles to %2 failed: %3</source>
        <translation>Schreiben von %1 Kacheln nach %2 fehlgeschlagen: %3</translation>
    </message>
    <message>
        <source>Reading the tiles of %1 failed: %2</source>
        <translation>Lesen der Kacheln von %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>The MBTiles file %1 has more than %2 metadata rows.</source>
        <translation>Die MBTiles-Datei %1 hat mehr als %2 Metadatenzeilen.</translation>
    </message>
    <message>
        <source>stopped: %1</source>
        <translation>abgebrochen: %1</translation>
    </message>
</context>
<context>
    <name>MbTilesMetadata</name>
    <message>
        <source>%1: &apos;%2&apos; is not a zoom level (0 to 30).</source>
        <translation>%1: „%2“ ist keine Zoomstufe (0 bis 30).</translation>
    </message>
    <message>
        <source>bounds: &apos;%1&apos; is not west,south,east,north in degrees.</source>
        <translation>bounds: „%1“ ist nicht West,Süd,Ost,Nord in Grad.</translation>
    </message>
    <message>
        <source>minzoom %1 is above maxzoom %2.</source>
        <translation>minzoom %1 liegt über maxzoom %2.</translation>
    </message>
</context>
<context>
    <name>MissionDifference</name>
    <message numerus="yes">
        <source>the vehicle holds %n waypoint(s), %1 were sent</source>
        <translation>
            <numerusform>das Fahrzeug enthält %n Wegpunkt, gesendet wurden %1</numerusform>
            <numerusform>das Fahrzeug enthält %n Wegpunkte, gesendet wurden %1</numerusform>
        </translation>
    </message>
    <message>
        <source>waypoint %1: </source>
        <translation>Wegpunkt %1: </translation>
    </message>
    <message>
        <source>the vehicle holds another position</source>
        <translation>das Fahrzeug enthält eine andere Position</translation>
    </message>
    <message>
        <source>altitude %1 m, sent %2 m</source>
        <translation>Höhe %1 m, gesendet %2 m</translation>
    </message>
    <message>
        <source>speed %1 m/s, sent %2 m/s</source>
        <translation>Geschwindigkeit %1 m/s, gesendet %2 m/s</translation>
    </message>
    <message>
        <source>acceptance radius %1 m, sent %2 m</source>
        <translation>Akzeptanzradius %1 m, gesendet %2 m</translation>
    </message>
    <message numerus="yes">
        <source>%n action(s), sent %1</source>
        <translation>
            <numerusform>%n Aktion, gesendet %1</numerusform>
            <numerusform>%n Aktionen, gesendet %1</numerusform>
        </translation>
    </message>
    <message>
        <source>action %1 (%2) differs</source>
        <translation>Aktion %1 (%2) weicht ab</translation>
    </message>
</context>
<context>
    <name>MissionError</name>
    <message>
        <source>(at %1)</source>
        <translation>(bei %1)</translation>
    </message>
</context>
<context>
    <name>MissionFiles</name>
    <message>
        <source>cannot open: %1</source>
        <translation>kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>unknown file type: use .sortie, .plan, .waypoints, .kml or .kmz</source>
        <translation>unbekannter Dateityp: Verwenden Sie .sortie, .plan, .waypoints, .kml oder .kmz</translation>
    </message>
    <message>
        <source>Sortie mission</source>
        <translation>Sortie-Mission</translation>
    </message>
    <message>
        <source>QGroundControl plan</source>
        <translation>QGroundControl-Plan</translation>
    </message>
    <message>
        <source>QGC WPL 110 waypoints</source>
        <translation>Wegpunkte (QGC WPL 110)</translation>
    </message>
    <message>
        <source>DJI WPML</source>
        <translation>DJI WPML</translation>
    </message>
    <message>
        <source>a KML file holds a polygon, not a mission: import it as an area-scan boundary</source>
        <translation>eine KML-Datei enthält ein Polygon, keine Mission: Importieren Sie es als Begrenzung eines Flächenscans</translation>
    </message>
    <message>
        <source>the mission has no route %1 (it has %2)</source>
        <translation>die Mission hat keine Route %1 (sie hat %2)</translation>
    </message>
    <message>
        <source>the mission has no route to write</source>
        <translation>die Mission hat keine Route zum Schreiben</translation>
    </message>
    <message>
        <source>the mission has %1 routes and a %2 file holds one: choose the route to write (sortie-plan convert --route N), or write .sortie or DJI WPML (.kmz), which hold them all</source>
        <translation>die Mission hat %1 Routen, und eine %2-Datei fasst eine: Wählen Sie die zu schreibende Route (sortie-plan convert --route N), oder schreiben Sie .sortie oder DJI WPML (.kmz), die alle fassen</translation>
    </message>
    <message>
        <source>Saving route &quot;%1&quot;</source>
        <translation>Speichern der Route „%1“</translation>
    </message>
    <message>
        <source>cannot write: %1</source>
        <translation>kann nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <source>the file is larger than %1 MiB</source>
        <translation>die Datei ist größer als %1 MiB</translation>
    </message>
</context>
<context>
    <name>MissionPage</name>
    <message>
        <source>Zones (%1)</source>
        <translation>Zonen (%1)</translation>
    </message>
    <message>
        <source>Click the centre line (%1 so far)</source>
        <translation>Mittellinie anklicken (bisher %1)</translation>
    </message>
    <message>
        <source>Click the corners of the area (%1 so far)</source>
        <translation>Ecken des Gebiets anklicken (bisher %1)</translation>
    </message>
    <message>
        <source>Click where it goes</source>
        <translation>Klicken, wo es hin soll</translation>
    </message>
    <message>
        <source>Create</source>
        <translation>Erstellen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Click the corners (%1 so far), or Shift+drag a box</source>
        <translation>Ecken anklicken (bisher %1) oder mit Umschalt+Ziehen ein Rechteck</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Fertig</translation>
    </message>
    <message>
        <source>2D</source>
        <translation>2D</translation>
    </message>
    <message>
        <source>3D</source>
        <translation>3D</translation>
    </message>
    <message>
        <source>Back to the map</source>
        <translation>Zurück zur Karte</translation>
    </message>
    <message>
        <source>The route, the ground and the zones in 3D</source>
        <translation>Route, Gelände und Zonen in 3D</translation>
    </message>
</context>
<context>
    <name>NfzConversion</name>
    <message>
        <source>its baseAltitude is not a number</source>
        <translation>ihre baseAltitude ist keine Zahl</translation>
    </message>
    <message>
        <source>its height %1 m is not a height (it must be 0 or more)</source>
        <translation>ihre Höhe %1 m ist keine gültige Höhe (sie muss 0 oder mehr betragen)</translation>
    </message>
    <message>
        <source>point %1 of its prism is not a position (latitude and longitude in radians)</source>
        <translation>Punkt %1 ihres Prismas ist keine Position (Breite und Länge in Radiant)</translation>
    </message>
    <message numerus="yes">
        <source>its prism has %n corner(s); a polygon needs 3</source>
        <translation>
            <numerusform>ihr Prisma hat %n Ecke; ein Polygon braucht 3</numerusform>
            <numerusform>ihr Prisma hat %n Ecken; ein Polygon braucht 3</numerusform>
        </translation>
    </message>
    <message>
        <source>its cone frustum has no centre (baseLatitude, baseLongitude in radians)</source>
        <translation>ihr Kegelstumpf hat keinen Mittelpunkt (baseLatitude, baseLongitude in Radiant)</translation>
    </message>
    <message>
        <source>its cone frustum&apos;s radii (base %1 m, top %2 m) are not a circle</source>
        <translation>die Radien ihres Kegelstumpfs (unten %1 m, oben %2 m) ergeben keinen Kreis</translation>
    </message>
    <message>
        <source>its cone frustum has two radii but no height</source>
        <translation>ihr Kegelstumpf hat zwei Radien, aber keine Höhe</translation>
    </message>
    <message>
        <source>its floor (%1) and ceiling (%2) are in different references; a server zone has one</source>
        <translation>ihre Untergrenze (%1) und Obergrenze (%2) haben verschiedene Bezüge; eine Serverzone hat einen</translation>
    </message>
    <message>
        <source>its heights are above home; a server zone&apos;s are AMSL or AGL</source>
        <translation>ihre Höhen beziehen sich auf den Home-Punkt; die einer Serverzone sind AMSL oder AGL</translation>
    </message>
    <message>
        <source>it starts from the ground with an AMSL ceiling; give it an AMSL floor or an AGL ceiling</source>
        <translation>sie beginnt am Boden mit einer AMSL-Obergrenze; geben Sie ihr eine AMSL-Untergrenze oder eine AGL-Obergrenze</translation>
    </message>
    <message>
        <source>NoFlightZone %1</source>
        <translation>NoFlightZone %1</translation>
    </message>
    <message>
        <source>UgCS server, NoFlightZone %1</source>
        <translation>UgCS-Server, NoFlightZone %1</translation>
    </message>
    <message>
        <source>it has both a prism and a cone frustum</source>
        <translation>sie hat sowohl ein Prisma als auch einen Kegelstumpf</translation>
    </message>
    <message>
        <source>it has no volume (neither a prism nor a cone frustum)</source>
        <translation>sie hat kein Volumen (weder Prisma noch Kegelstumpf)</translation>
    </message>
    <message>
        <source>its ceiling is below its floor</source>
        <translation>ihre Obergrenze liegt unter ihrer Untergrenze</translation>
    </message>
    <message>
        <source>the server&apos;s no-fly zones keep vehicles out; an inclusion zone cannot be one</source>
        <translation>die Flugverbotszonen des Servers halten Fahrzeuge fern; eine Einschlusszone kann keine davon sein</translation>
    </message>
    <message>
        <source>aerodrome zones are the server&apos;s own; only custom zones are changed</source>
        <translation>Flugplatzzonen gehören dem Server; nur eigene Zonen werden geändert</translation>
    </message>
    <message numerus="yes">
        <source>%n ring(s)</source>
        <translation>
            <numerusform>%n Ring</numerusform>
            <numerusform>%n Ringe</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>a server zone is one polygon without holes (this one has %n part(s), %1)</source>
        <translation>
            <numerusform>eine Serverzone ist ein Polygon ohne Löcher (diese hat %n Teil, %1)</numerusform>
            <numerusform>eine Serverzone ist ein Polygon ohne Löcher (diese hat %n Teile, %1)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>its polygon has %n corner(s); it needs 3</source>
        <translation>
            <numerusform>ihr Polygon hat %n Ecke; es braucht 3</numerusform>
            <numerusform>ihr Polygon hat %n Ecken; es braucht 3</numerusform>
        </translation>
    </message>
    <message>
        <source>a cone frustum needs a ceiling</source>
        <translation>ein Kegelstumpf braucht eine Obergrenze</translation>
    </message>
    <message>
        <source>NoFlightZone %1%2 was left out: %3</source>
        <translation>NoFlightZone %1%2 wurde ausgelassen: %3</translation>
    </message>
</context>
<context>
    <name>NumberField</name>
    <message>
        <source>Not a number: type it as %1</source>
        <translation>Keine Zahl: Schreiben Sie sie wie %1</translation>
    </message>
    <message>
        <source>From %1 to %2</source>
        <translation>Von %1 bis %2</translation>
    </message>
    <message>
        <source>At least %1</source>
        <translation>Mindestens %1</translation>
    </message>
    <message>
        <source>At most %1</source>
        <translation>Höchstens %1</translation>
    </message>
</context>
<context>
    <name>OfflineMapsDialog</name>
    <message>
        <source>Offline maps</source>
        <translation>Offline-Karten</translation>
    </message>
    <message>
        <source>From %1</source>
        <translation>Von %1</translation>
    </message>
    <message>
        <source>Choose a web tile server in Map source first.</source>
        <translation>Wählen Sie zuerst unter Kartenquelle einen Web-Kachelserver.</translation>
    </message>
    <message>
        <source>The open route</source>
        <translation>Die geöffnete Route</translation>
    </message>
    <message>
        <source>and</source>
        <translation>und</translation>
    </message>
    <message>
        <source>m around it</source>
        <translation>m darum herum</translation>
    </message>
    <message>
        <source>The map&apos;s view</source>
        <translation>Der Kartenausschnitt</translation>
    </message>
    <message>
        <source>Zoom from</source>
        <translation>Zoom von</translation>
    </message>
    <message>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <source>Pack file</source>
        <translation>Paketdatei</translation>
    </message>
    <message>
        <source>Attribution</source>
        <translation>Namensnennung</translation>
    </message>
    <message>
        <source>As the provider&apos;s usage policy asks, e.g. © OpenStreetMap contributors</source>
        <translation>Wie es die Nutzungsrichtlinie des Anbieters verlangt, z. B. © OpenStreetMap-Mitwirkende</translation>
    </message>
    <message>
        <source>Cache only: the map never uses the network (the pack, then the disk cache)</source>
        <translation>Nur Cache: Die Karte nutzt nie das Netzwerk (erst das Paket, dann der Festplatten-Cache)</translation>
    </message>
    <message>
        <source>Download</source>
        <translation>Herunterladen</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Draw an area</source>
        <translation>Gebiet zeichnen</translation>
    </message>
    <message>
        <source>Click its corners on the map, or Shift+drag a box</source>
        <translation>Ecken auf der Karte anklicken oder mit Umschalt+Ziehen ein Rechteck</translation>
    </message>
</context>
<context>
    <name>OpenQuestion</name>
    <message>
        <source>Unsaved edits</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>OrthophotoRenderer</name>
    <message>
        <source>the image is not georeferenced (no CRS or no geotransform)</source>
        <translation>das Bild ist nicht georeferenziert (kein KBS oder keine Geotransformation)</translation>
    </message>
    <message>
        <source>its extent cannot be placed on the map: %1</source>
        <translation>seine Ausdehnung lässt sich nicht auf der Karte platzieren: %1</translation>
    </message>
    <message>
        <source>PROJ gave no reason</source>
        <translation>PROJ nannte keinen Grund</translation>
    </message>
    <message>
        <source>no memory for a tile</source>
        <translation>kein Speicher für eine Kachel</translation>
    </message>
    <message>
        <source>%1: tile %2/%3/%4: %5</source>
        <translation>%1: Kachel %2/%3/%4: %5</translation>
    </message>
    <message>
        <source>the warp failed</source>
        <translation>die Entzerrung ist fehlgeschlagen</translation>
    </message>
    <message>
        <source>the warped tile cannot be read</source>
        <translation>die entzerrte Kachel kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>%1: tile size %2 is outside 1..%3</source>
        <translation>%1: Kachelgröße %2 liegt außerhalb von 1..%3</translation>
    </message>
</context>
<context>
    <name>OutsideDatabase</name>
    <message>
        <source>more than %1 steps</source>
        <translation>mehr als %1 Schritte</translation>
    </message>
    <message>
        <source>more than %1 rows</source>
        <translation>mehr als %1 Zeilen</translation>
    </message>
    <message>
        <source>SQLite refused the settings a file from outside is read with</source>
        <translation>SQLite hat die Einstellungen abgelehnt, mit denen eine Datei von außen gelesen wird</translation>
    </message>
</context>
<context>
    <name>PhotosDialog</name>
    <message>
        <source>Photos of the flight</source>
        <translation>Fotos des Flugs</translation>
    </message>
    <message>
        <source>The folder of the flight&apos;s photos</source>
        <translation>Der Ordner mit den Fotos des Flugs</translation>
    </message>
    <message>
        <source>Where the geotagged copies go</source>
        <translation>Wohin die georeferenzierten Kopien kommen</translation>
    </message>
    <message>
        <source>Photos</source>
        <translation>Fotos</translation>
    </message>
    <message>
        <source>a folder of JPEG, TIFF or DNG photos</source>
        <translation>ein Ordner mit JPEG-, TIFF- oder DNG-Fotos</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Wählen…</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>Camera clock behind the log (s)</source>
        <translation>Kamerauhr hinter dem Log (s)</translation>
    </message>
    <message>
        <source>Seconds added to each photo&apos;s time: how far the camera&apos;s clock is behind the log&apos;s (GNSS) time</source>
        <translation>Sekunden, die zur Zeit jedes Fotos addiert werden: wie weit die Kamerauhr hinter der (GNSS-)Zeit des Logs liegt</translation>
    </message>
    <message>
        <source>Place photos</source>
        <translation>Fotos verorten</translation>
    </message>
    <message>
        <source>Holes, largest first (shaded on the map):</source>
        <translation>Lücken, die größte zuerst (auf der Karte schattiert):</translation>
    </message>
    <message>
        <source>Not placed:</source>
        <translation>Nicht verortet:</translation>
    </message>
    <message>
        <source>Write geotagged copies…</source>
        <translation>Georeferenzierte Kopien schreiben…</translation>
    </message>
    <message>
        <source>Re-fly the gaps</source>
        <translation>Lücken nachfliegen</translation>
    </message>
    <message>
        <source>A route of an area scan per hole, with the survey&apos;s camera, height and overlap, opened in the mission editor</source>
        <translation>Eine Route mit einem Flächenscan pro Lücke, mit Kamera, Höhe und Überlappung der Vermessung, im Missionseditor geöffnet</translation>
    </message>
</context>
<context>
    <name>PrivateFiles</name>
    <message>
        <source>Cannot create the folder %1: %2 is not a folder</source>
        <translation>Der Ordner %1 kann nicht angelegt werden: %2 ist kein Ordner</translation>
    </message>
    <message>
        <source>Cannot create the folder %1: %2</source>
        <translation>Der Ordner %1 kann nicht angelegt werden: %2</translation>
    </message>
    <message>
        <source>Cannot create the folder %1</source>
        <translation>Der Ordner %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>Cannot create %1: %2</source>
        <translation>%1 kann nicht angelegt werden: %2</translation>
    </message>
    <message>
        <source>Cannot create a private folder in %1: %2</source>
        <translation>In %1 kann kein privater Ordner angelegt werden: %2</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source> in %1 s</source>
        <translation> in %1 s</translation>
    </message>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 min %2 s</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 km</source>
        <translation>%1 km</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>missed</source>
        <translation>verpasst</translation>
    </message>
    <message>
        <source>That vehicle is not in this log (it holds %1).</source>
        <translation>Dieses Fahrzeug ist nicht in diesem Protokoll (es enthält %1).</translation>
    </message>
    <message>
        <source>no vehicle</source>
        <translation>kein Fahrzeug</translation>
    </message>
    <message>
        <source>Route &quot;%1&quot; has fewer than two waypoints: there is nothing to compare.</source>
        <translation>Route „%1“ hat weniger als zwei Wegpunkte: Es gibt nichts zu vergleichen.</translation>
    </message>
    <message>
        <source>%1 has no track in this log to compare with.</source>
        <translation>%1 hat in diesem Protokoll keinen Track zum Vergleichen.</translation>
    </message>
    <message>
        <source>Route &quot;%1&quot; does not match %2: its waypoints are %3 km from anywhere %2 flew in this log.</source>
        <translation>Route „%1“ passt nicht zu %2: Ihre Wegpunkte liegen %3 km von allem entfernt, was %2 in diesem Protokoll geflogen ist.</translation>
    </message>
    <message>
        <source>%1 flown by %2, %3 to %4
</source>
        <translation>%1 geflogen von %2, %3 bis %4
</translation>
    </message>
    <message>
        <source>
waypoint  reached                    closest
</source>
        <translation>
Wegpunkt  erreicht                   geringster Abstand
</translation>
    </message>
    <message>
        <source>
leg      samples  cross-track max  mean      altitude max  mean
</source>
        <translation>
Teilstr.  Punkte   Querablage max   Mittel    Höhe max      Mittel
</translation>
    </message>
    <message>
        <source>
total: %1 reached, %2 missed; cross-track max %3, mean %4; altitude max %5, mean %6
</source>
        <translation>
Gesamt: %1 erreicht, %2 verpasst; Querablage max %3, Mittel %4; Höhe max %5, Mittel %6
</translation>
    </message>
    <message>
        <source>%1: no such file</source>
        <translation>%1: Datei nicht vorhanden</translation>
    </message>
    <message>
        <source>%1: cannot be opened: %2</source>
        <translation>%1: kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>no Sortie flight log header</source>
        <translation>kein Sortie-Flugprotokoll-Header</translation>
    </message>
    <message>
        <source>%1 is not a Sortie flight log (%2)</source>
        <translation>%1 ist kein Sortie-Flugprotokoll (%2)</translation>
    </message>
    <message>
        <source>%1: the vehicles cannot be read: %2</source>
        <translation>%1: Die Fahrzeuge können nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>the vehicle list is damaged: %1</source>
        <translation>Die Fahrzeugliste ist beschädigt: %1</translation>
    </message>
    <message>
        <source>unknown vehicle</source>
        <translation>unbekanntes Fahrzeug</translation>
    </message>
    <message>
        <source>stopped after %1 good blocks (%2): %3</source>
        <translation>nach %1 guten Blöcken angehalten (%2): %3</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>the telemetry cannot be read: %1</source>
        <translation>Die Telemetrie kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>the events stop after %1: %2</source>
        <translation>Die Ereignisse enden nach %1: %2</translation>
    </message>
    <message>
        <source>the events cannot be read: %1</source>
        <translation>Die Ereignisse können nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>the routes stop early: %1</source>
        <translation>Die Routen enden vorzeitig: %1</translation>
    </message>
    <message>
        <source>the routes cannot be read: %1</source>
        <translation>Die Routen können nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>file:     %1
</source>
        <translation>Datei:      %1
</translation>
    </message>
    <message>
        <source>span:     %1 to %2 (%3 s)
</source>
        <translation>Zeitraum:   %1 bis %2 (%3 s)
</translation>
    </message>
    <message>
        <source>DAMAGED:  read up to the last good record; %1
</source>
        <translation>BESCHÄDIGT: bis zum letzten guten Datensatz gelesen; %1
</translation>
    </message>
    <message>
        <source>vehicles: %1
</source>
        <translation>Fahrzeuge:  %1
</translation>
    </message>
    <message>
        <source>, %1 to %2</source>
        <translation>, %1 bis %2</translation>
    </message>
    <message>
        <source>    route uploaded %1: %2 waypoints
</source>
        <translation>    Route hochgeladen %1: %2 Wegpunkte
</translation>
    </message>
    <message>
        <source>
events:   %1
</source>
        <translation>
Ereignisse: %1
</translation>
    </message>
    <message>
        <source> (failed)</source>
        <translation> (fehlgeschlagen)</translation>
    </message>
    <message>
        <source>a replayed vehicle takes no commands</source>
        <translation>Ein wiedergegebenes Fahrzeug nimmt keine Befehle an</translation>
    </message>
    <message>
        <source>block %1 (vehicle row %2, from %3) is skipped: %4</source>
        <translation>Block %1 (Fahrzeugzeile %2, ab %3) wird übersprungen: %4</translation>
    </message>
    <message numerus="yes">
        <source>%n more damaged block(s) skipped</source>
        <translation>
            <numerusform>%n weiterer beschädigter Block übersprungen</numerusform>
            <numerusform>%n weitere beschädigte Blöcke übersprungen</numerusform>
        </translation>
    </message>
    <message>
        <source>read up to the last good record: %1</source>
        <translation>bis zum letzten guten Eintrag gelesen: %1</translation>
    </message>
    <message>
        <source>DAMAGED:  %1
</source>
        <translation>BESCHÄDIGT:  %1
</translation>
    </message>
    <message>
        <source>%1: cannot be opened: no private copy to recover it in (%2)</source>
        <translation>%1: kann nicht geöffnet werden: keine private Kopie zum Wiederherstellen (%2)</translation>
    </message>
    <message>
        <source>%1 is not a Sortie flight log (its %2 is a %3, not a table)</source>
        <translation>%1 ist kein Sortie-Flugprotokoll (sein %2 ist ein %3, keine Tabelle)</translation>
    </message>
    <message>
        <source>stopped: %1</source>
        <translation>abgebrochen: %1</translation>
    </message>
</context>
<context>
    <name>QgcFenceJson</name>
    <message>
        <source>expected [latitude, longitude]</source>
        <translation>[Breite, Länge] erwartet</translation>
    </message>
    <message>
        <source>latitude or longitude out of range</source>
        <translation>Breite oder Länge außerhalb des gültigen Bereichs</translation>
    </message>
    <message>
        <source>expected [latitude, longitude, altitude]</source>
        <translation>[Breite, Länge, Höhe] erwartet</translation>
    </message>
    <message>
        <source>a polygon needs at least 3 vertices, found %1</source>
        <translation>ein Polygon braucht mindestens 3 Eckpunkte, gefunden: %1</translation>
    </message>
    <message>
        <source>Geofence polygon at %1 was left out: %2</source>
        <translation>Geofence-Polygon bei %1 wurde ausgelassen: %2</translation>
    </message>
    <message>
        <source>the radius must be positive metres</source>
        <translation>der Radius muss eine positive Meterzahl sein</translation>
    </message>
    <message>
        <source>The geofence&apos;s breach return point at %1 was left out: %2</source>
        <translation>Der Rückkehrpunkt des Geofence für Verletzungen bei %1 wurde ausgelassen: %2</translation>
    </message>
    <message>
        <source>The geofence polygons at %1 were left out: %2</source>
        <translation>Die Geofence-Polygone bei %1 wurden ausgelassen: %2</translation>
    </message>
    <message>
        <source>Geofence circle at %1 was left out: %2</source>
        <translation>Der Geofence-Kreis bei %1 wurde ausgelassen: %2</translation>
    </message>
    <message>
        <source>The geofence circles at %1 were left out: %2</source>
        <translation>Die Geofence-Kreise bei %1 wurden ausgelassen: %2</translation>
    </message>
    <message>
        <source>Rally point at %1 was left out: %2</source>
        <translation>Der Sammelpunkt bei %1 wurde ausgelassen: %2</translation>
    </message>
    <message>
        <source>The rally points at %1 were left out: %2</source>
        <translation>Die Sammelpunkte bei %1 wurden ausgelassen: %2</translation>
    </message>
</context>
<context>
    <name>QgcPlanFormat</name>
    <message>
        <source>expected 7 params (or 4 and a &quot;coordinate&quot;), found %1</source>
        <translation>7 params (oder 4 und eine „coordinate“) erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>not a QGroundControl plan (fileType is not &quot;Plan&quot;)</source>
        <translation>kein QGroundControl-Plan (fileType ist nicht „Plan“)</translation>
    </message>
    <message>
        <source>plan version %1 is not supported (Sortie reads version 1)</source>
        <translation>Plan-Version %1 wird nicht unterstützt (Sortie liest Version 1)</translation>
    </message>
    <message>
        <source>mission version %1 is not supported (Sortie reads version 2)</source>
        <translation>Missions-Version %1 wird nicht unterstützt (Sortie liest Version 2)</translation>
    </message>
    <message>
        <source>the planned home position is out of range</source>
        <translation>die geplante Home-Position liegt außerhalb des gültigen Bereichs</translation>
    </message>
    <message>
        <source>complex item &quot;%1&quot; is not supported; Sortie imports surveys, corridor and structure scans</source>
        <translation>komplexes Element „%1“ wird nicht unterstützt; Sortie importiert Surveys, Korridor- und Strukturscans</translation>
    </message>
    <message>
        <source>unknown item type &quot;%1&quot;</source>
        <translation>unbekannter Elementtyp „%1“</translation>
    </message>
    <message>
        <source>A corridor was left out: %1</source>
        <translation>Ein Korridor wurde ausgelassen: %1</translation>
    </message>
    <message>
        <source>An area scan was left out: %1</source>
        <translation>Ein Flächenscan wurde ausgelassen: %1</translation>
    </message>
    <message>
        <source>The route has no home position: the first point was written as home, at 0 m AMSL.</source>
        <translation>Die Route hat keine Home-Position: Der erste Punkt wurde als Home-Punkt geschrieben, auf 0 m AMSL.</translation>
    </message>
</context>
<context>
    <name>QgcSurveyJson</name>
    <message>
        <source>latitude/longitude out of range</source>
        <translation>Breite/Länge außerhalb des gültigen Bereichs</translation>
    </message>
    <message>
        <source>a survey polygon needs at least 3 vertices, found %1</source>
        <translation>ein Survey-Polygon braucht mindestens 3 Eckpunkte, gefunden: %1</translation>
    </message>
    <message>
        <source>Custom Camera</source>
        <translation>Custom Camera</translation>
    </message>
    <message>
        <source>the survey&apos;s camera has neither a sensor nor footprints</source>
        <translation>die Kamera des Surveys hat weder einen Sensor noch Abdeckungen</translation>
    </message>
    <message>
        <source>%1: the survey&apos;s manual camera was replaced by one with the same footprints</source>
        <translation>%1: Die manuelle Kamera des Surveys wurde durch eine mit denselben Abdeckungen ersetzt</translation>
    </message>
    <message>
        <source>a %1 needs at least %2 points, found %3</source>
        <translation>%1: mindestens %2 Punkte nötig, gefunden: %3</translation>
    </message>
    <message>
        <source>%1: the camera &quot;%2&quot; is not one Sortie knows; it is kept by name, and the server must know it.</source>
        <translation>%1: Die Kamera „%2“ kennt Sortie nicht; sie wird unter ihrem Namen beibehalten, und der Server muss sie kennen.</translation>
    </message>
    <message>
        <source>the corridor&apos;s camera has no sensor to turn its distance into a ground sample distance</source>
        <translation>die Kamera des Korridors hat keinen Sensor, um ihren Abstand in eine Bodenauflösung umzurechnen</translation>
    </message>
    <message>
        <source>corridor centre line</source>
        <translation>Korridor-Mittellinie</translation>
    </message>
    <message>
        <source>structure polygon</source>
        <translation>Strukturpolygon</translation>
    </message>
    <message>
        <source>%1: the structure scan became a perimeter flight at %2 m%3.</source>
        <translation>%1: Der Strukturscan wurde zu einem Umfangsflug auf %2 m%3.</translation>
    </message>
    <message>
        <source>, its %1 layers as %1 loops at one height</source>
        <translation>, seine %1 Ebenen als %1 Runden auf einer Höhe</translation>
    </message>
</context>
<context>
    <name>RasterFootprint</name>
    <message>
        <source>the raster&apos;s geotransform cannot be inverted (a zero pixel size?)</source>
        <translation>die Georeferenzierung des Rasters ist nicht umkehrbar (Pixelgröße null?)</translation>
    </message>
    <message>
        <source>the raster has no pixels (%1×%2)</source>
        <translation>das Raster hat keine Pixel (%1×%2)</translation>
    </message>
    <message>
        <source>the raster&apos;s geotransform is not finite</source>
        <translation>die Georeferenzierung des Rasters ist nicht endlich</translation>
    </message>
</context>
<context>
    <name>RemoveSegmentsCommand</name>
    <message>
        <source>Delete %1</source>
        <translation>%1 löschen</translation>
    </message>
    <message>
        <source>Delete %1 rows</source>
        <translation>%1 Zeilen löschen</translation>
    </message>
</context>
<context>
    <name>ReorderSegmentsCommand</name>
    <message>
        <source>Move row %1</source>
        <translation>Zeile %1 verschieben</translation>
    </message>
    <message>
        <source>Move %1 rows</source>
        <translation>%1 Zeilen verschieben</translation>
    </message>
    <message>
        <source>Reverse rows %1-%2</source>
        <translation>Zeilen %1-%2 umkehren</translation>
    </message>
</context>
<context>
    <name>ReplayTimeline</name>
    <message>
        <source>Open a flight log</source>
        <translation>Flugprotokoll öffnen</translation>
    </message>
    <message>
        <source>Flight logs (*.sortielog)</source>
        <translation>Flugprotokolle (*.sortielog)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Export tracks</source>
        <translation>Tracks exportieren</translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation>Exportiert nach %1.</translation>
    </message>
    <message>
        <source>Open log…</source>
        <translation>Protokoll öffnen…</translation>
    </message>
    <message>
        <source>Server history…</source>
        <translation>Serververlauf…</translation>
    </message>
    <message>
        <source>REPLAY — %1</source>
        <translation>WIEDERGABE — %1</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>Previous event</source>
        <translation>Vorheriges Ereignis</translation>
    </message>
    <message>
        <source>Next event</source>
        <translation>Nächstes Ereignis</translation>
    </message>
    <message>
        <source>Jump to event (%1)</source>
        <translation>Zu Ereignis springen (%1)</translation>
    </message>
    <message>
        <source>Loading plots…</source>
        <translation>Diagramme werden geladen…</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportieren…</translation>
    </message>
    <message>
        <source>Back to live</source>
        <translation>Zurück zu live</translation>
    </message>
    <message>
        <source>Photos…</source>
        <translation>Fotos…</translation>
    </message>
</context>
<context>
    <name>RestoreDialog</name>
    <message>
        <source>Autosaved edits</source>
        <translation>Automatisch gesicherte Änderungen</translation>
    </message>
    <message>
        <source>Restore one of %1 unsaved routes?</source>
        <translation>Eine von %1 Routen mit ungespeicherten Änderungen wiederherstellen?</translation>
    </message>
    <message>
        <source>Restore unsaved edits?</source>
        <translation>Ungespeicherte Änderungen wiederherstellen?</translation>
    </message>
    <message>
        <source>Sortie did not close normally. These routes had unsaved edits, saved automatically. Choose one to see its changes; the others are kept and offered again at the next start.</source>
        <translation>Sortie wurde nicht normal beendet. Diese Routen hatten ungespeicherte Änderungen, die automatisch gesichert wurden. Wählen Sie eine, um ihre Änderungen zu sehen; die anderen bleiben erhalten und werden beim nächsten Start erneut angeboten.</translation>
    </message>
    <message>
        <source>Sortie did not close normally. Edits of “%1” were saved automatically at %2.</source>
        <translation>Sortie wurde nicht normal beendet. Änderungen an „%1“ wurden um %2 automatisch gesichert.</translation>
    </message>
    <message>
        <source>%1 — saved %2</source>
        <translation>%1 — gesichert %2</translation>
    </message>
    <message>
        <source>It belongs to %1.</source>
        <translation>Sie gehört zu %1.</translation>
    </message>
    <message>
        <source>Changes since the last save:</source>
        <translation>Änderungen seit dem letzten Speichern:</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>Start without these edits (the file is kept as a backup)</source>
        <translation>Ohne diese Änderungen starten (die Datei bleibt als Sicherung erhalten)</translation>
    </message>
    <message>
        <source>Later</source>
        <translation>Später</translation>
    </message>
    <message>
        <source>Keep them and decide after signing in</source>
        <translation>Behalten und nach der Anmeldung entscheiden</translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Wiederherstellen</translation>
    </message>
</context>
<context>
    <name>ResumePanel</name>
    <message>
        <source>Resume from the last photo</source>
        <translation>Ab dem letzten Foto fortsetzen</translation>
    </message>
    <message>
        <source>Resume from the last waypoint</source>
        <translation>Ab dem letzten Wegpunkt fortsetzen</translation>
    </message>
</context>
<context>
    <name>ResumeRoute</name>
    <message>
        <source>%1 cannot be resumed here: %2</source>
        <translation>%1 kann hier nicht fortgesetzt werden: %2</translation>
    </message>
    <message>
        <source>the take-off point is not known</source>
        <translation>der Startpunkt ist nicht bekannt</translation>
    </message>
    <message>
        <source>the route has nothing to fly</source>
        <translation>die Route hat nichts zu fliegen</translation>
    </message>
    <message>
        <source>none of the waypoints the vehicle reached is on this route&apos;s path: not this route&apos;s flight</source>
        <translation>keiner der erreichten Wegpunkte liegt auf dem Pfad dieser Route: kein Flug dieser Route</translation>
    </message>
    <message>
        <source>The last waypoint the vehicle reached is not one of the route&apos;s own: the rest starts at the route&apos;s point before it.</source>
        <translation>Der zuletzt erreichte Wegpunkt gehört nicht zur Route: der Rest beginnt am Punkt der Route davor.</translation>
    </message>
    <message>
        <source>where the last photo was taken is not known</source>
        <translation>wo das letzte Foto aufgenommen wurde, ist nicht bekannt</translation>
    </message>
    <message>
        <source>the last photo was taken %1 m from the route&apos;s path, more than the %2 m a flight of it strays: not this route&apos;s flight</source>
        <translation>das letzte Foto wurde %1 m vom Pfad der Route aufgenommen, mehr als die %2 m, die ein Flug abweicht: kein Flug dieser Route</translation>
    </message>
    <message>
        <source>The photos were taken every %1 s: the next one is taken as due %2 m on at the leg&apos;s speed.</source>
        <translation>Die Fotos wurden alle %1 s aufgenommen: das nächste gilt bei der Geschwindigkeit des Abschnitts %2 m weiter als fällig.</translation>
    </message>
    <message>
        <source>No photo series was running at the last photo: the rest starts where it was taken.</source>
        <translation>Beim letzten Foto lief keine Fotoserie: der Rest beginnt dort, wo es aufgenommen wurde.</translation>
    </message>
    <message>
        <source>the last photo was the route&apos;s last: nothing is left to fly</source>
        <translation>das letzte Foto war das letzte der Route: es bleibt nichts zu fliegen</translation>
    </message>
    <message>
        <source>the route was flown to its last point: nothing is left to fly</source>
        <translation>die Route wurde bis zu ihrem letzten Punkt geflogen: es bleibt nichts zu fliegen</translation>
    </message>
    <message>
        <source>%1 (resumed)</source>
        <translation>%1 (fortgesetzt)</translation>
    </message>
    <message>
        <source>Route</source>
        <translation>Route</translation>
    </message>
    <message>
        <source>Resumes %1, %2 m into the flight (%3 m left), after a take-off and a flight over at %4 m.</source>
        <translation>Setzt %1 fort, %2 m nach Flugbeginn (%3 m übrig), nach einem Start und einem Überflug in %4 m.</translation>
    </message>
    <message>
        <source>The photo series every %1 m starts again at the resume point.</source>
        <translation>Die Fotoserie alle %1 m beginnt am Fortsetzungspunkt erneut.</translation>
    </message>
    <message>
        <source>The photo series every %1 s starts again at the resume point.</source>
        <translation>Die Fotoserie alle %1 s beginnt am Fortsetzungspunkt erneut.</translation>
    </message>
    <message>
        <source>The gimbal is tilted to %1° there, as it was.</source>
        <translation>Der Gimbal wird dort wie zuvor auf %1° geneigt.</translation>
    </message>
    <message>
        <source>the place to resume from is not on the route&apos;s path</source>
        <translation>der Ort, an dem fortgesetzt werden soll, liegt nicht auf dem Pfad der Route</translation>
    </message>
    <message>
        <source>the place to resume from is %1 m from where the route&apos;s path is that far along</source>
        <translation>der Ort, an dem fortgesetzt werden soll, liegt %1 m von der Stelle entfernt, an der der Pfad der Route so weit ist</translation>
    </message>
</context>
<context>
    <name>RouteDiff</name>
    <message>
        <source>WP %1</source>
        <translation>WP %1</translation>
    </message>
    <message>
        <source>Scan %1</source>
        <translation>Scan %1</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>return home</source>
        <translation>Rückkehr</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>No changes</source>
        <translation>Keine Änderungen</translation>
    </message>
    <message>
        <source>1 change: </source>
        <translation>1 Änderung: </translation>
    </message>
    <message>
        <source>%1 changes: </source>
        <translation>%1 Änderungen: </translation>
    </message>
    <message>
        <source> and %1 more</source>
        <translation> und %1 weitere</translation>
    </message>
    <message>
        <source>name %1 → %2</source>
        <translation>Name %1 → %2</translation>
    </message>
    <message>
        <source>%1 %2 → %3 %4</source>
        <translation>%1 %2 → %3 %4</translation>
    </message>
    <message>
        <source>safe altitude</source>
        <translation>Sicherheitshöhe</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>maximum altitude</source>
        <translation>Maximalhöhe</translation>
    </message>
    <message>
        <source>initial speed</source>
        <translation>Anfangsgeschwindigkeit</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>maximum speed</source>
        <translation>Höchstgeschwindigkeit</translation>
    </message>
    <message>
        <source>corner radius</source>
        <translation>Kurvenradius</translation>
    </message>
    <message>
        <source>takeoff height</source>
        <translation>Starthöhe</translation>
    </message>
    <message>
        <source>vehicle profile %1 → %2</source>
        <translation>Fahrzeugprofil %1 → %2</translation>
    </message>
    <message>
        <source>vehicle profile %1 changed</source>
        <translation>Fahrzeugprofil %1 geändert</translation>
    </message>
    <message>
        <source>failsafe actions changed</source>
        <translation>Failsafe-Aktionen geändert</translation>
    </message>
    <message>
        <source>home set</source>
        <translation>Home-Punkt gesetzt</translation>
    </message>
    <message>
        <source>home removed</source>
        <translation>Home-Punkt entfernt</translation>
    </message>
    <message>
        <source>home moved %1 m</source>
        <translation>Home-Punkt um %1 m verschoben</translation>
    </message>
    <message>
        <source>home altitude %1 → %2 m</source>
        <translation>Höhe des Home-Punkts %1 → %2 m</translation>
    </message>
    <message>
        <source>end action %1 → %2</source>
        <translation>Endaktion %1 → %2</translation>
    </message>
    <message>
        <source>on</source>
        <translation>ein</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>aerodrome zone check</source>
        <translation>Prüfung der Flugplatzzonen</translation>
    </message>
    <message>
        <source>custom zone check</source>
        <translation>Prüfung eigener Zonen</translation>
    </message>
    <message>
        <source>%1 removed</source>
        <translation>%1 entfernt</translation>
    </message>
    <message>
        <source>%1 added</source>
        <translation>%1 hinzugefügt</translation>
    </message>
    <message>
        <source>%1 changed</source>
        <translation>%1 geändert</translation>
    </message>
    <message>
        <source>%1 moved %2 m</source>
        <translation>%1 um %2 m verschoben</translation>
    </message>
    <message>
        <source>altitude of %1 %2 m %3 → %4 m %5</source>
        <translation>Höhe von %1 %2 m %3 → %4 m %5</translation>
    </message>
    <message>
        <source>altitude of %1 %2 → %3 m</source>
        <translation>Höhe von %1 %2 → %3 m</translation>
    </message>
    <message>
        <source>speed of %1 %2 → %3 m/s</source>
        <translation>Geschwindigkeit von %1 %2 → %3 m/s</translation>
    </message>
    <message>
        <source>actions of %1: %2 → %3</source>
        <translation>Aktionen von %1: %2 → %3</translation>
    </message>
    <message>
        <source>turn at %1 %2 → %3</source>
        <translation>Kurvenart bei %1 %2 → %3</translation>
    </message>
    <message>
        <source>acceptance radius of %1 %2 → %3 m</source>
        <translation>Akzeptanzradius von %1 %2 → %3 m</translation>
    </message>
    <message>
        <source>%1 %2 → %3</source>
        <translation>%1 %2 → %3</translation>
    </message>
    <message>
        <source>figure of %1 reshaped</source>
        <translation>Figur von %1 umgeformt</translation>
    </message>
    <message>
        <source>%1 of %2 %3 → %4</source>
        <translation>%1 von %2 %3 → %4</translation>
    </message>
    <message>
        <source>%1 of %2 removed</source>
        <translation>%1 von %2 entfernt</translation>
    </message>
    <message>
        <source>actions of %1 changed</source>
        <translation>Aktionen von %1 geändert</translation>
    </message>
    <message>
        <source>area of %1 reshaped</source>
        <translation>Fläche von %1 umgeformt</translation>
    </message>
    <message>
        <source>area of %1 reshaped (%2 → %3 corners)</source>
        <translation>Fläche von %1 umgeformt (%2 → %3 Ecken)</translation>
    </message>
    <message>
        <source>%1 of %2 %3 → %4 %5</source>
        <translation>%1 von %2 %3 → %4 %5</translation>
    </message>
    <message>
        <source>altitude</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <source>altitude of %1 now %2</source>
        <translation>Höhe von %1 jetzt %2</translation>
    </message>
    <message>
        <source>%1 now flies by ground sample distance</source>
        <translation>%1 fliegt jetzt nach Bodenauflösung (GSD)</translation>
    </message>
    <message>
        <source>%1 now flies by altitude</source>
        <translation>%1 fliegt jetzt nach Höhe</translation>
    </message>
    <message>
        <source>front overlap</source>
        <translation>Längsüberlappung</translation>
    </message>
    <message>
        <source>side overlap</source>
        <translation>Querüberlappung</translation>
    </message>
    <message>
        <source>direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>turnaround</source>
        <translation>Wendestrecke</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>camera of %1 %2 → %3</source>
        <translation>Kamera von %1 %2 → %3</translation>
    </message>
    <message>
        <source>camera of %1 changed</source>
        <translation>Kamera von %1 geändert</translation>
    </message>
    <message>
        <source>planned start %1</source>
        <translation>geplanter Start %1</translation>
    </message>
    <message>
        <source>planned start removed: now</source>
        <translation>geplanter Start entfernt: jetzt</translation>
    </message>
    <message>
        <source>authorisation for %1: %2</source>
        <translation>Genehmigung für %1: %2</translation>
    </message>
    <message>
        <source>authorisation for %1 removed</source>
        <translation>Genehmigung für %1 entfernt</translation>
    </message>
</context>
<context>
    <name>RouteEndurance</name>
    <message>
        <source>No energy profile: choose the vehicle&apos;s profile file</source>
        <translation>Kein Energieprofil: Wählen Sie die Profildatei des Fahrzeugs</translation>
    </message>
    <message>
        <source>The route has no points</source>
        <translation>Die Route hat keine Punkte</translation>
    </message>
</context>
<context>
    <name>RoutePanel</name>
    <message>
        <source>Import a route</source>
        <translation>Route importieren</translation>
    </message>
    <message>
        <source>Routes (*.sortie *.plan *.waypoints *.txt *.kml *.kmz)</source>
        <translation>Routen (*.sortie *.plan *.waypoints *.txt *.kml *.kmz)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <source>The vehicle&apos;s energy profile</source>
        <translation>Energieprofil des Fahrzeugs</translation>
    </message>
    <message>
        <source>Energy profiles (*.json)</source>
        <translation>Energieprofile (*.json)</translation>
    </message>
    <message>
        <source>Export the route</source>
        <translation>Route exportieren</translation>
    </message>
    <message>
        <source>Sortie (*.sortie)</source>
        <translation>Sortie (*.sortie)</translation>
    </message>
    <message>
        <source>QGroundControl plan (*.plan)</source>
        <translation>QGroundControl-Plan (*.plan)</translation>
    </message>
    <message>
        <source>Waypoint list (*.waypoints)</source>
        <translation>Wegpunktliste (*.waypoints)</translation>
    </message>
    <message>
        <source>KML (*.kml)</source>
        <translation>KML (*.kml)</translation>
    </message>
    <message>
        <source>DJI Pilot 2 route, WPML (*.kmz)</source>
        <translation>DJI-Pilot-2-Route, WPML (*.kmz)</translation>
    </message>
    <message>
        <source>Choose a route…</source>
        <translation>Route wählen…</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Öffnen</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Save on the server, under its lock (Ctrl+S)</source>
        <translation>Auf dem Server speichern, unter seiner Sperre (Strg+S)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <source>Undo %1 (Ctrl+Z)</source>
        <translation>%1 rückgängig machen (Strg+Z)</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <source>Redo %1 (Ctrl+Shift+Z)</source>
        <translation>%1 wiederholen (Strg+Umschalt+Z)</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Delete the selected waypoints (Del)</source>
        <translation>Die ausgewählten Wegpunkte löschen (Entf)</translation>
    </message>
    <message>
        <source>Area scan</source>
        <translation>Flächenscan</translation>
    </message>
    <message>
        <source>Draw an area to scan: click its corners on the map</source>
        <translation>Ein zu scannendes Gebiet zeichnen: seine Ecken auf der Karte anklicken</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>Importieren…</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportieren…</translation>
    </message>
    <message>
        <source>Zone checks…</source>
        <translation>Zonenprüfung…</translation>
    </message>
    <message>
        <source>Which no-fly zones the server&apos;s processing refuses the route for</source>
        <translation>Für welche Flugverbotszonen die Verarbeitung auf dem Server die Route ablehnt</translation>
    </message>
    <message>
        <source>Refuse crossing aerodrome zones</source>
        <translation>Queren von Flugplatzzonen ablehnen</translation>
    </message>
    <message>
        <source>Refuse crossing custom zones</source>
        <translation>Queren eigener Zonen ablehnen</translation>
    </message>
    <message>
        <source>Process</source>
        <translation>Verarbeiten</translation>
    </message>
    <message>
        <source>Prepare the route for the chosen vehicle, as the upload will, and show what it would fly (Ctrl+P)</source>
        <translation>Die Route für das gewählte Fahrzeug so vorbereiten, wie es der Upload tut, und zeigen, was es fliegen würde (Strg+P)</translation>
    </message>
    <message>
        <source>Vehicle…</source>
        <translation>Fahrzeug…</translation>
    </message>
    <message>
        <source>Upload</source>
        <translation>Hochladen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Yours (version %1, edited) against theirs (version %2, grey on the map):</source>
        <translation>Ihre Fassung (Version %1, bearbeitet) gegen die andere (Version %2, grau auf der Karte):</translation>
    </message>
    <message>
        <source>They changed: %1</source>
        <translation>Dort geändert: %1</translation>
    </message>
    <message>
        <source>Keep mine (overwrite theirs)</source>
        <translation>Meine behalten (andere überschreiben)</translation>
    </message>
    <message>
        <source>Take theirs (undo brings mine back)</source>
        <translation>Andere übernehmen (Rückgängig holt meine zurück)</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Waypoints</source>
        <translation>Wegpunkte</translation>
    </message>
    <message>
        <source>Photos</source>
        <translation>Fotos</translation>
    </message>
    <message>
        <source>Conflicts with other vehicles</source>
        <translation>Konflikte mit anderen Fahrzeugen</translation>
    </message>
    <message>
        <source>%1:%2  leg %3 · %4 (%5): %6 m across, %7 m in height</source>
        <translation>%1:%2  Teilstrecke %3 · %4 (%5): %6 m seitlich, %7 m in der Höhe</translation>
    </message>
    <message>
        <source>flying</source>
        <translation>fliegt</translation>
    </message>
    <message>
        <source>uploaded</source>
        <translation>hochgeladen</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Energie</translation>
    </message>
    <message>
        <source>%1 Wh</source>
        <translation>%1 Wh</translation>
    </message>
    <message numerus="yes">
        <source>%n batteries</source>
        <translation>
            <numerusform>%n Akku</numerusform>
            <numerusform>%n Akkus</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 % left</source>
        <translation>%1 % übrig</translation>
    </message>
    <message>
        <source>No return</source>
        <translation>Keine Rückkehr</translation>
    </message>
    <message>
        <source>unknown: no home</source>
        <translation>unbekannt: kein Home-Punkt</translation>
    </message>
    <message>
        <source>after %1 (leg %2)</source>
        <translation>nach %1 (Teilstrecke %2)</translation>
    </message>
    <message>
        <source>none: home in reach</source>
        <translation>nirgends: Home-Punkt in Reichweite</translation>
    </message>
    <message>
        <source>Beyond this point of the route, flying straight home no longer lands with the reserve</source>
        <translation>Ab diesem Punkt der Route landet ein direkter Rückflug zum Home-Punkt nicht mehr mit der Reserve</translation>
    </message>
    <message>
        <source>Load an energy profile to see whether the battery lasts.</source>
        <translation>Laden Sie ein Energieprofil, um zu sehen, ob der Akku reicht.</translation>
    </message>
    <message>
        <source>Profile</source>
        <translation>Profil</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>unnamed</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keins</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Laden…</translation>
    </message>
    <message>
        <source>The vehicle&apos;s energy profile: a JSON file, e.g. from sortie-log fit</source>
        <translation>Das Energieprofil des Fahrzeugs: eine JSON-Datei, z. B. aus sortie-log fit</translation>
    </message>
    <message>
        <source>Wind</source>
        <translation>Wind</translation>
    </message>
    <message>
        <source>Wind speed, m/s</source>
        <translation>Windgeschwindigkeit, m/s</translation>
    </message>
    <message>
        <source>m/s from</source>
        <translation>m/s aus</translation>
    </message>
    <message>
        <source>The direction the wind blows from, degrees clockwise from north</source>
        <translation>Richtung, aus der der Wind weht, in Grad im Uhrzeigersinn ab Nord</translation>
    </message>
    <message>
        <source>Select the segment</source>
        <translation>Segment auswählen</translation>
    </message>
    <message>
        <source>Planned start</source>
        <translation>Geplanter Start</translation>
    </message>
    <message>
        <source>now (or e.g. %1)</source>
        <translation>jetzt (oder z. B. %1)</translation>
    </message>
    <message>
        <source>Year-month-day hours:minutes, your time zone; empty: the flight starts now</source>
        <translation>Jahr-Monat-Tag Stunden:Minuten, Ihre Zeitzone; leer: der Flug beginnt jetzt</translation>
    </message>
</context>
<context>
    <name>RouteValidator</name>
    <message>
        <source>%1: the position is not valid.</source>
        <translation>%1: Die Position ist ungültig.</translation>
    </message>
    <message>
        <source>The route needs at least two points; it has %1.</source>
        <translation>Die Route braucht mindestens zwei Punkte; sie hat %1.</translation>
    </message>
    <message numerus="yes">
        <source>%n AMSL altitude(s), the first at %1, were not checked against the route&apos;s limits: the take-off elevation is unknown.</source>
        <translation>
            <numerusform>%n AMSL-Höhe (bei %1) wurde nicht gegen die Grenzen der Route geprüft: Die Geländehöhe am Startpunkt ist unbekannt.</numerusform>
            <numerusform>%n AMSL-Höhen, die erste bei %1, wurden nicht gegen die Grenzen der Route geprüft: Die Geländehöhe am Startpunkt ist unbekannt.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: altitude %2 is below the route&apos;s safe altitude of %3 m.</source>
        <translation>%1: Höhe %2 liegt unter der Sicherheitshöhe der Route von %3 m.</translation>
    </message>
    <message>
        <source>%1: the speed must be positive.</source>
        <translation>%1: Die Geschwindigkeit muss positiv sein.</translation>
    </message>
    <message>
        <source>%1: speed %2 m/s is above the vehicle&apos;s limit of %3 m/s.</source>
        <translation>%1: Geschwindigkeit %2 m/s liegt über der Grenze des Fahrzeugs von %3 m/s.</translation>
    </message>
    <message>
        <source>%1: Sortie does not know the algorithm %2; the server checks it when it processes the route.</source>
        <translation>%1: Sortie kennt den Algorithmus %2 nicht; der Server prüft ihn, wenn er die Route verarbeitet.</translation>
    </message>
    <message>
        <source>%1 repeats %2.</source>
        <translation>%1 wiederholt %2.</translation>
    </message>
    <message>
        <source>%1 is %2 but %3 is %4: the climb between them is not estimated.</source>
        <translation>%1 ist %2, aber %3 ist %4: Der Steigflug dazwischen wird nicht abgeschätzt.</translation>
    </message>
    <message>
        <source>The route</source>
        <translation>Die Route</translation>
    </message>
    <message>
        <source>%1: %2 m above the take-off point (altitude %3); the route&apos;s limit is %4 m above it.</source>
        <translation>%1: %2 m über dem Startpunkt (Höhe %3); die Grenze der Route liegt %4 m darüber.</translation>
    </message>
</context>
<context>
    <name>SbsFeed</name>
    <message>
        <source>line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
</context>
<context>
    <name>ScaleBarLength</name>
    <message>
        <source>%1 km</source>
        <translation>%1 km</translation>
    </message>
    <message>
        <source>%1 mi</source>
        <translation>%1 mi</translation>
    </message>
    <message>
        <source>%1 ft</source>
        <translation>%1 ft</translation>
    </message>
</context>
<context>
    <name>Scene3DView</name>
    <message>
        <source>The 3D view needs OpenGL: start Sortie with QSG_RHI_BACKEND=opengl.</source>
        <translation>Die 3D-Ansicht braucht OpenGL: starten Sie Sortie mit QSG_RHI_BACKEND=opengl.</translation>
    </message>
    <message>
        <source>Open a route to see it in 3D.</source>
        <translation>Öffnen Sie eine Route, um sie in 3D zu sehen.</translation>
    </message>
    <message>
        <source>Purple ground: no elevation data there.</source>
        <translation>Violetter Boden: dort keine Höhendaten.</translation>
    </message>
    <message>
        <source>Vertical exaggeration</source>
        <translation>Überhöhung</translation>
    </message>
    <message>
        <source>Fit route</source>
        <translation>Route einpassen</translation>
    </message>
</context>
<context>
    <name>SegmentEditor</name>
    <message>
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <source>Advanced parameters</source>
        <translation>Erweiterte Parameter</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
</context>
<context>
    <name>SegmentEditorModel</name>
    <message>
        <source>Acceptance radius</source>
        <translation>Akzeptanzradius</translation>
    </message>
    <message>
        <source>Sensor width (mm)</source>
        <translation>Sensorbreite (mm)</translation>
    </message>
    <message>
        <source>Sensor height (mm)</source>
        <translation>Sensorhöhe (mm)</translation>
    </message>
    <message>
        <source>Focal length (mm)</source>
        <translation>Brennweite (mm)</translation>
    </message>
    <message>
        <source>Image width (px)</source>
        <translation>Bildbreite (px)</translation>
    </message>
    <message>
        <source>Image height (px)</source>
        <translation>Bildhöhe (px)</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <source>Side distance (0: from the camera)</source>
        <translation>Bahnabstand (0: aus der Kamera)</translation>
    </message>
</context>
<context>
    <name>SegmentParameters</name>
    <message>
        <source>%1 needs a number, not &quot;%2&quot;.</source>
        <translation>%1 braucht eine Zahl, nicht „%2“.</translation>
    </message>
    <message>
        <source>altitudeType is AGL or AMSL, not &quot;%1&quot;.</source>
        <translation>altitudeType ist AGL oder AMSL, nicht „%1“.</translation>
    </message>
    <message>
        <source>camera needs a name.</source>
        <translation>camera braucht einen Namen.</translation>
    </message>
    <message>
        <source>An area scan has no parameter &quot;%1&quot;.</source>
        <translation>Ein Flächenscan hat keinen Parameter „%1“.</translation>
    </message>
    <message>
        <source>wpTurnType is STOP_AND_TURN, STRAIGHT, SPLINE or BANK_TURN, not &quot;%1&quot;.</source>
        <translation>wpTurnType ist STOP_AND_TURN, STRAIGHT, SPLINE oder BANK_TURN, nicht „%1“.</translation>
    </message>
    <message>
        <source>A waypoint has no parameter &quot;%1&quot;.</source>
        <translation>Ein Wegpunkt hat keinen Parameter „%1“.</translation>
    </message>
    <message>
        <source>%1 has no parameter &quot;%2&quot;.</source>
        <translation>%1 hat keinen Parameter „%2“.</translation>
    </message>
    <message>
        <source>%1 cannot take that value.</source>
        <translation>%1 kann diesen Wert nicht annehmen.</translation>
    </message>
    <message>
        <source>%1 is true or false, not &quot;%2&quot;.</source>
        <translation>%1 ist true oder false, nicht „%2“.</translation>
    </message>
    <message>
        <source>%1 must be from %2 to below %3.</source>
        <translation>%1 muss von %2 bis unter %3 liegen.</translation>
    </message>
    <message>
        <source>%1 must be from %2 to %3.</source>
        <translation>%1 muss von %2 bis %3 liegen.</translation>
    </message>
</context>
<context>
    <name>SegmentPlanner</name>
    <message>
        <source>The segment has no point</source>
        <translation>Das Segment hat keinen Punkt</translation>
    </message>
    <message>
        <source>Point 1 is not a position on the globe</source>
        <translation>Punkt 1 ist keine Position auf dem Globus</translation>
    </message>
    <message>
        <source>The circle has no centre point</source>
        <translation>Der Kreis hat keinen Mittelpunkt</translation>
    </message>
    <message>
        <source>The circle&apos;s centre is not a position on the globe</source>
        <translation>Der Mittelpunkt des Kreises ist keine Position auf dem Globus</translation>
    </message>
    <message>
        <source>The circle needs a positive radius (metres, the figure&apos;s first parameter)</source>
        <translation>Der Kreis braucht einen positiven Radius (Meter, der erste Parameter der Figur)</translation>
    </message>
    <message>
        <source>The circle&apos;s radius of %1 m is over the %2 m a segment may span</source>
        <translation>Der Kreisradius von %1 m übersteigt die %2 m, die ein Segment umfassen darf</translation>
    </message>
    <message>
        <source>loops: %1 laps of %2 points are too many</source>
        <translation>loops: %1 Runden mit je %2 Punkten sind zu viele</translation>
    </message>
    <message numerus="yes">
        <source>Orbit of %1 m radius: %n lap(s) of %2 points, %3</source>
        <translation>
            <numerusform>Kreisflug mit %1 m Radius: %n Runde mit %2 Punkten, %3</numerusform>
            <numerusform>Kreisflug mit %1 m Radius: %n Runden mit je %2 Punkten, %3</numerusform>
        </translation>
    </message>
    <message>
        <source>clockwise</source>
        <translation>im Uhrzeigersinn</translation>
    </message>
    <message>
        <source>counter-clockwise</source>
        <translation>gegen den Uhrzeigersinn</translation>
    </message>
    <message>
        <source>Point %1 is not a position on the globe (latitude and longitude in range)</source>
        <translation>Punkt %1 ist keine Position auf dem Globus (Breite und Länge im gültigen Bereich)</translation>
    </message>
    <message>
        <source>speed: the segment needs a positive speed</source>
        <translation>speed: Das Segment braucht eine positive Geschwindigkeit</translation>
    </message>
    <message>
        <source>No planner knows the algorithm &apos;%1&apos;</source>
        <translation>Kein Planer kennt den Algorithmus „%1“</translation>
    </message>
</context>
<context>
    <name>SegmentWaypoints</name>
    <message>
        <source>cannot be planned</source>
        <translation>lässt sich nicht planen</translation>
    </message>
    <message>
        <source>only a UgCS server that knows %1 can plan it</source>
        <translation>nur ein UgCS-Server, der %1 kennt, kann es planen</translation>
    </message>
    <message>
        <source>no such segment</source>
        <translation>kein solches Segment</translation>
    </message>
</context>
<context>
    <name>ServerAction</name>
    <message>
        <source>Server action</source>
        <translation>Serveraktion</translation>
    </message>
</context>
<context>
    <name>ServerAddress</name>
    <message>
        <source>the server address is empty (expected host:port)</source>
        <translation>die Serveradresse ist leer (erwartet: Host:Port)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; opens an IPv6 address with [ but never closes it</source>
        <translation>„%1“ öffnet eine IPv6-Adresse mit [, schließt sie aber nie</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has text after the IPv6 address that is not :port</source>
        <translation>„%1“ hat nach der IPv6-Adresse Text, der nicht :Port ist</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an IPv6 address</source>
        <translation>„%1“ ist keine IPv6-Adresse</translation>
    </message>
    <message>
        <source>write an IPv6 server address in brackets: [%1]:3334</source>
        <translation>Schreiben Sie eine IPv6-Serveradresse in eckigen Klammern: [%1]:3334</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no host name</source>
        <translation>„%1“ hat keinen Hostnamen</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a host name (expected host:port, e.g. localhost:3334)</source>
        <translation>„%1“ ist kein Hostname (erwartet: Host:Port, z. B. localhost:3334)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a port number (1 to 65535)</source>
        <translation>„%1“ ist keine Portnummer (1 bis 65535)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is a URL: give the server as host:port, e.g. localhost:3334 (or tls://host:port over TLS)</source>
        <translation>„%1“ ist eine URL: Geben Sie den Server als Host:Port an, z. B. localhost:3334 (oder tls://host:port über TLS)</translation>
    </message>
</context>
<context>
    <name>ServerHistoryDialog</name>
    <message>
        <source>Server history</source>
        <translation>Serververlauf</translation>
    </message>
    <message>
        <source>Vehicle</source>
        <translation>Fahrzeug</translation>
    </message>
    <message>
        <source>From (UTC)</source>
        <translation>Von (UTC)</translation>
    </message>
    <message>
        <source>To (UTC)</source>
        <translation>Bis (UTC)</translation>
    </message>
    <message>
        <source>Last hour</source>
        <translation>Letzte Stunde</translation>
    </message>
    <message>
        <source>Fetch and replay</source>
        <translation>Abrufen und wiedergeben</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
</context>
<context>
    <name>ServerZoneReply</name>
    <message>
        <source>the server gave no reason</source>
        <translation>der Server hat keinen Grund genannt</translation>
    </message>
</context>
<context>
    <name>SetNfzChecksCommand</name>
    <message>
        <source>Check aerodrome zones</source>
        <translation>Flugplatzzonen prüfen</translation>
    </message>
    <message>
        <source>Do not check aerodrome zones</source>
        <translation>Flugplatzzonen nicht prüfen</translation>
    </message>
    <message>
        <source>Check custom zones</source>
        <translation>Eigene Zonen prüfen</translation>
    </message>
    <message>
        <source>Do not check custom zones</source>
        <translation>Eigene Zonen nicht prüfen</translation>
    </message>
</context>
<context>
    <name>ShortcutHelp</name>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <source>On the map</source>
        <translation>Auf der Karte</translation>
    </message>
    <message>
        <source>Esc closes this help.</source>
        <translation>Esc schließt diese Hilfe.</translation>
    </message>
</context>
<context>
    <name>Shortcuts</name>
    <message>
        <source>Pan the map (Shift: faster)</source>
        <translation>Karte verschieben (Umschalt: schneller)</translation>
    </message>
    <message>
        <source>Zoom in / out (also the mouse wheel and pinch)</source>
        <translation>Vergrößern / verkleinern (auch Mausrad und Zwei-Finger-Zoom)</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Ziehen</translation>
    </message>
    <message>
        <source>Pan the map</source>
        <translation>Karte verschieben</translation>
    </message>
    <message>
        <source>Shift+Drag</source>
        <translation>Umschalt+Ziehen</translation>
    </message>
    <message>
        <source>Select waypoints in a rectangle (Ctrl+Shift adds)</source>
        <translation>Wegpunkte in einem Rechteck auswählen (Strg+Umschalt fügt hinzu)</translation>
    </message>
    <message>
        <source>Click</source>
        <translation>Klick</translation>
    </message>
    <message>
        <source>Add a waypoint; on a leg: insert one; on a waypoint: select (Ctrl toggles, Shift extends)</source>
        <translation>Wegpunkt hinzufügen; auf einer Teilstrecke: einen einfügen; auf einem Wegpunkt: auswählen (Strg schaltet um, Umschalt erweitert)</translation>
    </message>
    <message>
        <source>Drag a waypoint</source>
        <translation>Wegpunkt ziehen</translation>
    </message>
    <message>
        <source>Move it, or the whole selection</source>
        <translation>Ihn verschieben, oder die ganze Auswahl</translation>
    </message>
    <message>
        <source>Show or hide this help</source>
        <translation>Diese Hilfe ein- oder ausblenden</translation>
    </message>
    <message>
        <source>Login page</source>
        <translation>Anmeldeseite</translation>
    </message>
    <message>
        <source>Mission page</source>
        <translation>Missionsseite</translation>
    </message>
    <message>
        <source>Live telemetry page</source>
        <translation>Live-Telemetrie-Seite</translation>
    </message>
    <message>
        <source>Save the route on the server</source>
        <translation>Route auf dem Server speichern</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <source>Delete the selected waypoints</source>
        <translation>Ausgewählte Wegpunkte löschen</translation>
    </message>
    <message>
        <source>Process the route on the server</source>
        <translation>Route auf dem Server verarbeiten</translation>
    </message>
    <message>
        <source>Choose the map source</source>
        <translation>Kartenquelle wählen</translation>
    </message>
    <message>
        <source>Focus the map (then arrows and +/− move it)</source>
        <translation>Karte fokussieren (dann bewegen Pfeiltasten und +/− sie)</translation>
    </message>
    <message>
        <source>Full screen on or off</source>
        <translation>Vollbild ein oder aus</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Beenden</translation>
    </message>
</context>
<context>
    <name>SortieFormat</name>
    <message>
        <source>not a valid UgCS %1</source>
        <translation>kein gültiges UgCS-%1</translation>
    </message>
    <message>
        <source>missing &quot;AGL&quot; or &quot;AMSL&quot;</source>
        <translation>„AGL“ oder „AMSL“ fehlt</translation>
    </message>
    <message>
        <source>expected &quot;AGL&quot; or &quot;AMSL&quot;</source>
        <translation>„AGL“ oder „AMSL“ erwartet</translation>
    </message>
    <message>
        <source>unknown value &quot;%1&quot;</source>
        <translation>unbekannter Wert „%1“</translation>
    </message>
    <message>
        <source>latitude out of range</source>
        <translation>Breite außerhalb des gültigen Bereichs</translation>
    </message>
    <message>
        <source>longitude out of range</source>
        <translation>Länge außerhalb des gültigen Bereichs</translation>
    </message>
    <message>
        <source>latitude/longitude out of range</source>
        <translation>Breite/Länge außerhalb des gültigen Bereichs</translation>
    </message>
    <message>
        <source>expected &quot;altitude&quot; or &quot;groundSampleDistance&quot;</source>
        <translation>„altitude“ oder „groundSampleDistance“ erwartet</translation>
    </message>
    <message>
        <source>no figure type %1</source>
        <translation>kein Figurtyp %1</translation>
    </message>
    <message>
        <source>unknown segment type &quot;%1&quot;</source>
        <translation>unbekannter Segmenttyp „%1“</translation>
    </message>
    <message>
        <source>expected &quot;none&quot; or &quot;returnHome&quot;</source>
        <translation>„none“ oder „returnHome“ erwartet</translation>
    </message>
    <message>
        <source>not a Sortie mission file (&quot;format&quot; is not &quot;sortie-mission&quot;)</source>
        <translation>keine Sortie-Missionsdatei („format“ ist nicht „sortie-mission“)</translation>
    </message>
    <message>
        <source>schema version %1 does not exist</source>
        <translation>Schema-Version %1 gibt es nicht</translation>
    </message>
    <message>
        <source>written by a newer Sortie (schema %1); this one reads up to schema %2</source>
        <translation>von einer neueren Sortie-Version geschrieben (Schema %1); diese liest bis Schema %2</translation>
    </message>
    <message>
        <source>expected a date and time in UTC, e.g. 2026-06-06T18:00:00Z</source>
        <translation>Datum und Uhrzeit in UTC erwartet, z. B. 2026-06-06T18:00:00Z</translation>
    </message>
    <message>
        <source>an authorisation needs the zone&apos;s identifier</source>
        <translation>eine Genehmigung braucht die Kennung der Zone</translation>
    </message>
</context>
<context>
    <name>StatusBar</name>
    <message>
        <source>zoom %1</source>
        <translation>Zoom %1</translation>
    </message>
</context>
<context>
    <name>TelemetryFieldNames</name>
    <message>
        <source>Latitude</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Altitude (AMSL)</source>
        <translation>Höhe (ü. NN)</translation>
    </message>
    <message>
        <source>Altitude above home</source>
        <translation>Höhe über Start</translation>
    </message>
    <message>
        <source>Roll</source>
        <translation>Rollwinkel</translation>
    </message>
    <message>
        <source>Pitch</source>
        <translation>Nickwinkel</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Steuerkurs</translation>
    </message>
    <message>
        <source>Course</source>
        <translation>Kurs über Grund</translation>
    </message>
    <message>
        <source>Ground speed</source>
        <translation>Geschwindigkeit über Grund</translation>
    </message>
    <message>
        <source>Air speed</source>
        <translation>Fluggeschwindigkeit</translation>
    </message>
    <message>
        <source>Vertical speed</source>
        <translation>Vertikalgeschwindigkeit</translation>
    </message>
    <message>
        <source>Battery voltage</source>
        <translation>Akkuspannung</translation>
    </message>
    <message>
        <source>Battery current</source>
        <translation>Akkustrom</translation>
    </message>
    <message>
        <source>Battery remaining</source>
        <translation>Akku-Restladung</translation>
    </message>
    <message>
        <source>GPS fix</source>
        <translation>GPS-Fix</translation>
    </message>
    <message>
        <source>Satellites</source>
        <translation>Satelliten</translation>
    </message>
    <message>
        <source>HDOP</source>
        <translation>HDOP</translation>
    </message>
    <message>
        <source>Home latitude</source>
        <translation>Breite des Startpunkts</translation>
    </message>
    <message>
        <source>Home longitude</source>
        <translation>Länge des Startpunkts</translation>
    </message>
    <message>
        <source>Home altitude (AMSL)</source>
        <translation>Höhe des Startpunkts (ü. NN)</translation>
    </message>
    <message>
        <source>Armed</source>
        <translation>Scharf</translation>
    </message>
    <message>
        <source>Flight mode</source>
        <translation>Flugmodus</translation>
    </message>
    <message>
        <source>Mission state</source>
        <translation>Missionsstatus</translation>
    </message>
    <message>
        <source>Current waypoint</source>
        <translation>Aktueller Wegpunkt</translation>
    </message>
    <message>
        <source>Waypoints reached</source>
        <translation>Erreichte Wegpunkte</translation>
    </message>
    <message>
        <source>Waypoints on board</source>
        <translation>Wegpunkte an Bord</translation>
    </message>
    <message>
        <source>Fence breached</source>
        <translation>Geofence verletzt</translation>
    </message>
    <message>
        <source>Fence breaches</source>
        <translation>Geofence-Verletzungen</translation>
    </message>
</context>
<context>
    <name>TelemetryPage</name>
    <message>
        <source>Vehicles</source>
        <translation>Fahrzeuge</translation>
    </message>
    <message>
        <source>No vehicles. Log in to a server or connect a VCI vehicle.</source>
        <translation>Keine Fahrzeuge. Melden Sie sich an einem Server an oder verbinden Sie ein VCI-Fahrzeug.</translation>
    </message>
    <message>
        <source>Command together with the other ticked vehicles</source>
        <translation>Zusammen mit den anderen markierten Fahrzeugen steuern</translation>
    </message>
    <message>
        <source>Vehicle %1</source>
        <translation>Fahrzeug %1</translation>
    </message>
    <message>
        <source>A vehicle reached directly over VCI: tcp://host:port or serial:///dev/ttyX?baud=57600</source>
        <translation>Ein direkt über VCI erreichtes Fahrzeug: tcp://host:port oder serial:///dev/ttyX?baud=57600</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Fit all</source>
        <translation>Alle zeigen</translation>
    </message>
    <message>
        <source>Show every vehicle on the map</source>
        <translation>Alle Fahrzeuge auf der Karte zeigen</translation>
    </message>
    <message>
        <source>Follow</source>
        <translation>Folgen</translation>
    </message>
    <message>
        <source>Keep the chosen vehicle in the middle of the map</source>
        <translation>Das gewählte Fahrzeug in der Kartenmitte halten</translation>
    </message>
    <message>
        <source>Fly %1 to %2?</source>
        <translation>%1 nach %2 fliegen lassen?</translation>
    </message>
    <message>
        <source>Plot this field too</source>
        <translation>Dieses Feld auch darstellen</translation>
    </message>
    <message>
        <source>1 min</source>
        <translation>1 min</translation>
    </message>
    <message>
        <source>5 min</source>
        <translation>5 min</translation>
    </message>
    <message>
        <source>30 min</source>
        <translation>30 min</translation>
    </message>
    <message>
        <source>Remove from the plot</source>
        <translation>Aus dem Diagramm entfernen</translation>
    </message>
    <message>
        <source>All vehicles</source>
        <translation>Alle Fahrzeuge</translation>
    </message>
    <message>
        <source>Compare these fields across every vehicle</source>
        <translation>Diese Felder über alle Fahrzeuge vergleichen</translation>
    </message>
    <message>
        <source>Video</source>
        <translation>Video</translation>
    </message>
    <message>
        <source>Show the chosen vehicle&apos;s video over the map</source>
        <translation>Das Video des gewählten Fahrzeugs über der Karte zeigen</translation>
    </message>
</context>
<context>
    <name>TerrainFollow</name>
    <message>
        <source>Waiting for terrain data from %1</source>
        <translation>Warten auf Geländedaten von %1</translation>
    </message>
    <message>
        <source>No terrain data %1 m along the pass (tried: %2): terrain following needs the ground everywhere</source>
        <translation>Keine Geländedaten bei %1 m entlang der Bahn (versucht: %2): Geländefolgeflug braucht überall Geländedaten</translation>
    </message>
</context>
<context>
    <name>TerrainProfile</name>
    <message>
        <source>%1, point %2</source>
        <translation>%1, Punkt %2</translation>
    </message>
    <message>
        <source>Waypoint %1</source>
        <translation>Wegpunkt %1</translation>
    </message>
    <message>
        <source>Leg %1 (%2 → %3)</source>
        <translation>Teilstrecke %1 (%2 → %3)</translation>
    </message>
</context>
<context>
    <name>TerrainRule</name>
    <message>
        <source>Waypoint %1</source>
        <translation>Wegpunkt %1</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <source>%1 m above the ground</source>
        <translation>%1 m über Grund</translation>
    </message>
    <message>
        <source>%1 m below the ground</source>
        <translation>%1 m unter Grund</translation>
    </message>
    <message>
        <source> (too low from %1 m to %2 m along it)</source>
        <translation> (zu tief von %1 m bis %2 m entlang der Teilstrecke)</translation>
    </message>
    <message>
        <source>%1 flies %2 at %3 m along it%4, closer than the safe distance of %5 m.</source>
        <translation>%1 fliegt %3 m nach ihrem Beginn %2%4, näher als der Sicherheitsabstand von %5 m.</translation>
    </message>
    <message>
        <source>%1: no terrain data from %2 m to %3 m along it</source>
        <translation>%1: keine Geländedaten von %2 m bis %3 m entlang der Teilstrecke</translation>
    </message>
    <message>
        <source>No terrain data from %1 m along %2 to %3 m along %4</source>
        <translation>Keine Geländedaten von %1 m auf %2 bis %3 m auf %4</translation>
    </message>
    <message>
        <source>%1 (tried: %2); the clearance there is not checked.</source>
        <translation>%1 (versucht: %2); der Bodenabstand wird dort nicht geprüft.</translation>
    </message>
    <message>
        <source>%1: the altitude is above home, but there is no terrain data at home (tried: %2), so the height above sea level is unknown.</source>
        <translation>%1: Die Höhe bezieht sich auf den Startpunkt, aber für den Startpunkt gibt es keine Geländedaten (versucht: %2), daher ist die Höhe über dem Meeresspiegel unbekannt.</translation>
    </message>
    <message>
        <source>%1: the altitude is above the ground, but there is no terrain data there (tried: %2), so the height above sea level is unknown.</source>
        <translation>%1: Die Höhe bezieht sich auf den Boden, aber dort gibt es keine Geländedaten (versucht: %2), daher ist die Höhe über dem Meeresspiegel unbekannt.</translation>
    </message>
    <message>
        <source>%1 flies up to %2 m above the ground at %3 m along it; the open category allows %4 m above the surface.</source>
        <translation>%1 fliegt %3 m nach ihrem Beginn bis zu %2 m über dem Boden; die offene Kategorie erlaubt %4 m über der Oberfläche.</translation>
    </message>
</context>
<context>
    <name>TileArea</name>
    <message>
        <source>The area is not a valid latitude/longitude box (south %1, west %2, north %3, east %4).</source>
        <translation>Das Gebiet ist kein gültiges Breiten-/Längen-Rechteck (Süd %1, West %2, Nord %3, Ost %4).</translation>
    </message>
    <message>
        <source>An area needs at least three corners (it has %1).</source>
        <translation>Ein Gebiet braucht mindestens drei Ecken (es hat %1).</translation>
    </message>
    <message>
        <source>Corner %1 of the area is not a latitude/longitude (%2, %3).</source>
        <translation>Ecke %1 des Gebiets ist keine Breite/Länge (%2, %3).</translation>
    </message>
    <message>
        <source>The area&apos;s edge from corner %1 crosses the antimeridian: draw it as two areas.</source>
        <translation>Die Kante des Gebiets ab Ecke %1 quert den Antimeridian: Zeichnen Sie es als zwei Gebiete.</translation>
    </message>
    <message>
        <source>The area&apos;s edges from corner %1 and corner %2 cross: draw it without crossing.</source>
        <translation>Die Kanten des Gebiets ab Ecke %1 und Ecke %2 kreuzen sich: zeichnen Sie es ohne Kreuzung.</translation>
    </message>
</context>
<context>
    <name>TileResponse</name>
    <message>
        <source>larger than %1 MiB: not read</source>
        <translation>größer als %1 MiB: nicht gelesen</translation>
    </message>
</context>
<context>
    <name>TileUrlTemplate</name>
    <message>
        <source>No tile URL template is set.</source>
        <translation>Keine Kachel-URL-Vorlage festgelegt.</translation>
    </message>
    <message>
        <source>The tile URL template is not a valid URL: %1</source>
        <translation>Die Kachel-URL-Vorlage ist keine gültige URL: %1</translation>
    </message>
    <message>
        <source>The tile URL template must start with http://, https:// or file://.</source>
        <translation>Die Kachel-URL-Vorlage muss mit http://, https:// oder file:// beginnen.</translation>
    </message>
    <message>
        <source>The tile URL template needs {z}, {x} and {y} (or {-y}).</source>
        <translation>Die Kachel-URL-Vorlage braucht {z}, {x} und {y} (oder {-y}).</translation>
    </message>
</context>
<context>
    <name>TlsServerIdentity</name>
    <message>
        <source>this Qt has no TLS backend (%1)</source>
        <translation>diesem Qt fehlt ein TLS-Backend (%1)</translation>
    </message>
    <message>
        <source>%1 holds no PEM certificate</source>
        <translation>%1 enthält kein PEM-Zertifikat</translation>
    </message>
    <message>
        <source>%1 holds no unencrypted PEM RSA or EC private key</source>
        <translation>%1 enthält keinen unverschlüsselten privaten PEM-Schlüssel (RSA oder EC)</translation>
    </message>
</context>
<context>
    <name>TlsVerdict</name>
    <message>
        <source>%1 sent no certificate</source>
        <translation>%1 hat kein Zertifikat gesendet</translation>
    </message>
    <message>
        <source>the pinned fingerprint for %1 is not a SHA-256 fingerprint (64 hex digits): %2</source>
        <translation>der festgelegte Fingerabdruck für %1 ist kein SHA-256-Fingerabdruck (64 Hexadezimalziffern): %2</translation>
    </message>
    <message>
        <source>%1 showed a certificate that is not the pinned one: pinned SHA-256 %2, shown SHA-256 %3</source>
        <translation>%1 hat ein anderes als das festgelegte Zertifikat gezeigt: festgelegt SHA-256 %2, gezeigt SHA-256 %3</translation>
    </message>
    <message>
        <source>the certificate of %1 has changed since it was first trusted: remembered SHA-256 %2, now SHA-256 %3. Someone may be in between; if the server&apos;s certificate was replaced on purpose, forget the remembered one</source>
        <translation>das Zertifikat von %1 hat sich geändert, seit ihm zum ersten Mal vertraut wurde: gespeichert SHA-256 %2, jetzt SHA-256 %3. Vielleicht sitzt jemand dazwischen; wurde das Zertifikat des Servers absichtlich ersetzt, vergessen Sie das gespeicherte</translation>
    </message>
    <message>
        <source>the certificate of %1 (SHA-256 %2) is not trusted by this system (%3), and there is no pinned or remembered one</source>
        <translation>dem Zertifikat von %1 (SHA-256 %2) vertraut dieses System nicht (%3), und es gibt kein festgelegtes oder gespeichertes</translation>
    </message>
</context>
<context>
    <name>UploadQuestion</name>
    <message>
        <source>Upload the route?</source>
        <translation>Route hochladen?</translation>
    </message>
    <message>
        <source>Upload without saving</source>
        <translation>Ohne Speichern hochladen</translation>
    </message>
    <message>
        <source>Upload</source>
        <translation>Hochladen</translation>
    </message>
    <message>
        <source>Save and upload</source>
        <translation>Speichern und hochladen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>UploadReview</name>
    <message>
        <source>%1 Fix it before %2.</source>
        <translation>%1 Bitte vor dem %2 beheben.</translation>
    </message>
    <message numerus="yes">
        <source>%1 (and %n more error(s)) Fix them before %2.</source>
        <translation>
            <numerusform>%1 (und %n weiterer Fehler) Bitte vor dem %2 beheben.</numerusform>
            <numerusform>%1 (und %n weitere Fehler) Bitte vor dem %2 beheben.</numerusform>
        </translation>
    </message>
    <message>
        <source>Upload</source>
        <translation>Hochladen</translation>
    </message>
    <message>
        <source>uploading</source>
        <translation>Hochladen</translation>
    </message>
    <message>
        <source>The route has edits that are not saved: the vehicle would fly what is on screen, not what the server holds.</source>
        <translation>Die Route hat ungespeicherte Änderungen: Das Fahrzeug würde fliegen, was auf dem Bildschirm ist, nicht was der Server hat.</translation>
    </message>
    <message numerus="yes">
        <source>The route has %n warning(s):</source>
        <translation>
            <numerusform>Die Route hat %n Warnung:</numerusform>
            <numerusform>Die Route hat %n Warnungen:</numerusform>
        </translation>
    </message>
    <message>
        <source>Upload to %1?</source>
        <translation>Auf %1 hochladen?</translation>
    </message>
    <message>
        <source>Saving</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>saving</source>
        <translation>Speichern</translation>
    </message>
</context>
<context>
    <name>UploadedFenceAlerts</name>
    <message>
        <source>route fence</source>
        <translation>Geofence der Route</translation>
    </message>
</context>
<context>
    <name>ValidationGate</name>
    <message numerus="yes">
        <source>%1 refused: the route has %n validation error(s). %2 Fix them, or override explicitly.</source>
        <translation>
            <numerusform>%1 abgelehnt: Die Route hat %n Validierungsfehler. %2 Beheben Sie ihn oder übergehen Sie ihn ausdrücklich.</numerusform>
            <numerusform>%1 abgelehnt: Die Route hat %n Validierungsfehler. %2 Beheben Sie sie oder übergehen Sie sie ausdrücklich.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>VciConnection</name>
    <message>
        <source>the connection to the vehicle was closed</source>
        <translation>die Verbindung zum Fahrzeug wurde geschlossen</translation>
    </message>
    <message>
        <source>the device was closed</source>
        <translation>das Gerät wurde geschlossen</translation>
    </message>
    <message>
        <source>the device was destroyed</source>
        <translation>das Gerät wurde zerstört</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid VCI URI</source>
        <translation>„%1“ ist keine gültige VCI-URI</translation>
    </message>
    <message>
        <source>a ground station does not send NOTIFY</source>
        <translation>eine Bodenstation sendet kein NOTIFY</translation>
    </message>
    <message>
        <source>not connected to the vehicle</source>
        <translation>keine Verbindung zum Fahrzeug</translation>
    </message>
    <message>
        <source>no answer in time (it waited behind other requests)</source>
        <translation>keine rechtzeitige Antwort (sie wartete hinter anderen Anfragen)</translation>
    </message>
    <message>
        <source>writing to the vehicle failed: %1</source>
        <translation>Schreiben an das Fahrzeug fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>the vehicle sent an answer (%1) to no request</source>
        <translation>das Fahrzeug hat eine Antwort (%1) ohne Anfrage gesendet</translation>
    </message>
    <message>
        <source>unreadable message from the vehicle at byte %1: %2</source>
        <translation>unlesbare Nachricht vom Fahrzeug bei Byte %1: %2</translation>
    </message>
    <message>
        <source>%1: the vehicle answered %2 %3</source>
        <translation>%1: Das Fahrzeug antwortete %2 %3</translation>
    </message>
    <message>
        <source>the vehicle did not answer in time</source>
        <translation>das Fahrzeug hat nicht rechtzeitig geantwortet</translation>
    </message>
</context>
<context>
    <name>VciEndpoint</name>
    <message>
        <source>&quot;%1&quot; is not a URL: %2</source>
        <translation>„%1“ ist keine URL: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names no serial device</source>
        <translation>„%1“ nennt kein serielles Gerät</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: unknown serial setting &quot;%2&quot; (baud, databits, parity, stopbits, flow)</source>
        <translation>„%1“: unbekannte serielle Einstellung „%2“ (baud, databits, parity, stopbits, flow)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2=%3 is not a valid value</source>
        <translation>„%1“: %2=%3 ist kein gültiger Wert</translation>
    </message>
    <message>
        <source>&quot;%1&quot; needs a host and a port: %2://host:port</source>
        <translation>„%1“ braucht einen Host und einen Port: %2://host:port</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: unknown setting &quot;%2&quot; (vci+tls:// knows sha256=)</source>
        <translation>„%1“: unbekannte Einstellung „%2“ (vci+tls:// kennt sha256=)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: sha256=%2 is not a SHA-256 fingerprint (64 hex digits)</source>
        <translation>„%1“: sha256=%2 ist kein SHA-256-Fingerabdruck (64 Hexadezimalziffern)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: use tcp://host:port, vci+tls://host:port or serial:/dev/name</source>
        <translation>„%1“: verwenden Sie tcp://host:port, vci+tls://host:port oder serial:/dev/name</translation>
    </message>
</context>
<context>
    <name>VciFenceBuilder</name>
    <message>
        <source>zone &apos;%1&apos;: its AGL limits need the ground under it, which no terrain source has; a vehicle cannot be given it</source>
        <translation>Zone „%1“: Ihre AGL-Grenzen brauchen das Gelände darunter, das keine Geländequelle hat; sie kann keinem Fahrzeug übergeben werden</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: no ground under it, so its AGL limits were dropped (the vehicle keeps out of the whole column)</source>
        <translation>Zone „%1“: kein Gelände darunter, daher wurden ihre AGL-Grenzen verworfen (das Fahrzeug hält sich aus der ganzen Säule fern)</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: over ground from %2 to %3 m its AGL limits leave no room in AMSL</source>
        <translation>Zone „%1“: Über Gelände von %2 bis %3 m lassen ihre AGL-Grenzen in AMSL keinen Raum</translation>
    </message>
    <message>
        <source>%1 (hole %2)</source>
        <translation>%1 (Loch %2)</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: its holes are closed on the vehicle (a fence polygon has none)</source>
        <translation>Zone „%1“: Ihre Löcher werden auf dem Fahrzeug geschlossen (ein Geofence-Polygon hat keine)</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: a cone that narrows to a point cannot keep a vehicle in</source>
        <translation>Zone „%1“: Ein Kegel, der sich zu einem Punkt verengt, kann kein Fahrzeug einschließen</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: its cone is a cylinder of radius %2 m on the vehicle</source>
        <translation>Zone „%1“: Ihr Kegel wird auf dem Fahrzeug ein Zylinder mit %2 m Radius</translation>
    </message>
    <message>
        <source>route fence</source>
        <translation>Geofence der Route</translation>
    </message>
    <message>
        <source>the fence cannot be sent: %1</source>
        <translation>der Geofence kann nicht gesendet werden: %1</translation>
    </message>
    <message numerus="yes">
        <source>fence: %1 of the route&apos;s own, %n airspace zone(s) near it; on a breach the vehicle will %2</source>
        <translation>
            <numerusform>Geofence: %1 aus der Route, %n Luftraumzone in der Nähe; bei einer Verletzung: %2</numerusform>
            <numerusform>Geofence: %1 aus der Route, %n Luftraumzonen in der Nähe; bei einer Verletzung: %2</numerusform>
        </translation>
    </message>
    <message>
        <source>return home</source>
        <translation>Rückkehr</translation>
    </message>
    <message>
        <source>land</source>
        <translation>Landung</translation>
    </message>
    <message>
        <source>hold</source>
        <translation>Position halten</translation>
    </message>
    <message>
        <source>the fence cannot be made: its zones are not the airspace&apos;s</source>
        <translation>der Geofence kann nicht erstellt werden: seine Zonen stammen nicht aus dem Luftraum</translation>
    </message>
</context>
<context>
    <name>VciMissionPlanner</name>
    <message>
        <source>the route has no waypoints to fly</source>
        <translation>die Route hat keine Wegpunkte zum Fliegen</translation>
    </message>
</context>
<context>
    <name>VciTransport</name>
    <message>
        <source>closed by the operator</source>
        <translation>vom Bediener geschlossen</translation>
    </message>
    <message>
        <source>reconnecting at the operator&apos;s request</source>
        <translation>Neuverbindung auf Wunsch des Bedieners</translation>
    </message>
    <message>
        <source>the vehicle closed the connection</source>
        <translation>das Fahrzeug hat die Verbindung geschlossen</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>not connected over TLS: %1</source>
        <translation>keine Verbindung über TLS: %1</translation>
    </message>
</context>
<context>
    <name>VciVehicleLink</name>
    <message>
        <source>connection to %1 lost: %2</source>
        <translation>Verbindung zu %1 verloren: %2</translation>
    </message>
    <message>
        <source>disconnected by the operator</source>
        <translation>vom Bediener getrennt</translation>
    </message>
    <message>
        <source>left its fence &apos;%1&apos;</source>
        <translation>hat seinen Geofence „%1“ verlassen</translation>
    </message>
    <message>
        <source>entered the exclusion zone &apos;%1&apos;</source>
        <translation>ist in die Ausschlusszone „%1“ eingeflogen</translation>
    </message>
    <message>
        <source>returning home</source>
        <extracomment>What a vehicle does after a fence breach: &quot;fence breach: left its fence &apos;A&apos;; returning home&quot;.</extracomment>
        <translation>kehrt zum Home-Punkt zurück</translation>
    </message>
    <message>
        <source>action unknown</source>
        <extracomment>After a fence breach, the vehicle named no action: &quot;fence breach: left its fence &apos;A&apos;; action unknown&quot;.</extracomment>
        <translation>Aktion unbekannt</translation>
    </message>
    <message>
        <source>fence breach: %1; %2</source>
        <translation>Geofence-Verletzung: %1; %2</translation>
    </message>
    <message>
        <source>the ground under the route did not arrive from %1 in %2 s</source>
        <translation>die Geländedaten unter der Route kamen nicht innerhalb von %2 s von %1</translation>
    </message>
    <message>
        <source>the vehicle refused the fence: %1</source>
        <translation>das Fahrzeug hat den Geofence abgelehnt: %1</translation>
    </message>
    <message>
        <source>the fence could not be read back: %1</source>
        <translation>der Geofence konnte nicht zurückgelesen werden: %1</translation>
    </message>
    <message>
        <source>the vehicle&apos;s fence cannot be read: %1</source>
        <translation>der Geofence des Fahrzeugs kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>the vehicle holds another fence than the one sent (%1 items sent, %2 held)</source>
        <translation>das Fahrzeug enthält einen anderen Geofence als den gesendeten (%1 Elemente gesendet, %2 vorhanden)</translation>
    </message>
    <message>
        <source>the vehicle&apos;s mission cannot be read: %1</source>
        <translation>die Mission des Fahrzeugs kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a parameter name</source>
        <translation>„%1“ ist kein Parametername</translation>
    </message>
    <message>
        <source>landing</source>
        <extracomment>What a vehicle does after a fence breach: &quot;fence breach: left its fence &apos;A&apos;; landing&quot;.</extracomment>
        <translation>landet</translation>
    </message>
    <message>
        <source>holding</source>
        <extracomment>What a vehicle does after a fence breach: &quot;fence breach: left its fence &apos;A&apos;; holding&quot;.</extracomment>
        <translation>hält die Position</translation>
    </message>
    <message>
        <source>the fence cannot be made: this link was given no fence builder</source>
        <translation>der Geofence kann nicht erstellt werden: diese Verbindung hat keinen Geofence-Ersteller erhalten</translation>
    </message>
    <message>
        <source>%1: first secure connection; its certificate is now trusted and remembered. Compare its SHA-256 fingerprint with the vehicle&apos;s: %2</source>
        <translation>%1: erste sichere Verbindung; seinem Zertifikat wird nun vertraut, und es ist gespeichert. Vergleichen Sie seinen SHA-256-Fingerabdruck mit dem des Fahrzeugs: %2</translation>
    </message>
    <message>
        <source>a photo report was not understood: %1</source>
        <translation>eine Fotomeldung war unverständlich: %1</translation>
    </message>
</context>
<context>
    <name>Vehicle</name>
    <message>
        <source>mode %1</source>
        <translation>Modus %1</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a flight mode</source>
        <translation>„%1“ ist kein Flugmodus</translation>
    </message>
    <message>
        <source>takeoff to %1 m</source>
        <translation>Start auf %1 m</translation>
    </message>
    <message>
        <source>return home</source>
        <translation>Rückkehr</translation>
    </message>
</context>
<context>
    <name>VerticalDatum</name>
    <message>
        <source>ellipsoidal (%1)</source>
        <translation>ellipsoidisch (%1)</translation>
    </message>
    <message>
        <source>orthometric (%1)</source>
        <translation>orthometrisch (%1)</translation>
    </message>
    <message>
        <source>not stated</source>
        <translation>nicht angegeben</translation>
    </message>
</context>
<context>
    <name>VideoPanel</name>
    <message>
        <source>rtsp://, udp://:5600 or an .sdp file</source>
        <translation>rtsp://, udp://:5600 oder eine .sdp-Datei</translation>
    </message>
    <message>
        <source>This vehicle&apos;s video: empty plays the stream the vehicle publishes; a URL typed here overrides it and is remembered.</source>
        <translation>Das Video dieses Fahrzeugs: leer spielt den Stream, den das Fahrzeug meldet; eine hier eingegebene URL ersetzt ihn und wird gemerkt.</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Aufnehmen</translation>
    </message>
    <message>
        <source>Recording to %1</source>
        <translation>Aufnahme nach %1</translation>
    </message>
    <message>
        <source>Record this video as received, beside the flight log</source>
        <translation>Dieses Video wie empfangen aufnehmen, neben dem Flugprotokoll</translation>
    </message>
    <message>
        <source>Map</source>
        <translation>Karte</translation>
    </message>
    <message>
        <source>Swap</source>
        <translation>Tauschen</translation>
    </message>
</context>
<context>
    <name>VideoSource</name>
    <message>
        <source>latency &apos;%1&apos;: expected milliseconds from 0 to 10000</source>
        <translation>Latenz „%1“: erwartet Millisekunden von 0 bis 10000</translation>
    </message>
    <message>
        <source>codec &apos;%1&apos;: expected h264 or h265</source>
        <translation>Codec „%1“: erwartet h264 oder h265</translation>
    </message>
    <message>
        <source>payload &apos;%1&apos;: expected a dynamic RTP payload type from 96 to 127</source>
        <translation>Payload „%1“: erwartet ein dynamischer RTP-Payload-Typ von 96 bis 127</translation>
    </message>
    <message>
        <source>unknown option &apos;%1&apos;</source>
        <translation>unbekannte Option „%1“</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an IP address to listen on</source>
        <translation>„%1“ ist keine IP-Adresse zum Empfangen</translation>
    </message>
    <message>
        <source>port %1 is out of range</source>
        <translation>Port %1 liegt außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>an RTSP URL needs a host: rtsp://host:8554/path</source>
        <translation>eine RTSP-URL braucht einen Host: rtsp://host:8554/pfad</translation>
    </message>
    <message>
        <source>port 0 is out of range</source>
        <translation>Port 0 liegt außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>SDP file %1: %2</source>
        <translation>SDP-Datei %1: %2</translation>
    </message>
    <message>
        <source>RTSP over TCP %1</source>
        <translation>RTSP über TCP %1</translation>
    </message>
    <message>
        <source>RTSP %1</source>
        <translation>RTSP %1</translation>
    </message>
    <message>
        <source>RTP/UDP %1 port %2</source>
        <translation>RTP/UDP %1 Port %2</translation>
    </message>
    <message>
        <source>MPEG-TS/UDP port %1</source>
        <translation>MPEG-TS/UDP Port %1</translation>
    </message>
    <message>
        <source>no video URL</source>
        <translation>keine Video-URL</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a URL</source>
        <translation>„%1“ ist keine URL</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a video URL Sortie plays: use rtsp://, rtspt://, udp://, udp+ts:// or an .sdp file</source>
        <translation>„%1“ ist keine Video-URL, die Sortie abspielt: verwenden Sie rtsp://, rtspt://, udp://, udp+ts:// oder eine .sdp-Datei</translation>
    </message>
    <message>
        <source>SDP file %1 cannot be read as SDP</source>
        <translation>SDP-Datei %1 kann nicht als SDP gelesen werden</translation>
    </message>
    <message>
        <source>SDP file %1: port %2 is out of range</source>
        <translation>SDP-Datei %1: Port %2 liegt außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>SDP file %1: the video has no payload type</source>
        <translation>SDP-Datei %1: das Video hat keinen Payload-Typ</translation>
    </message>
    <message>
        <source>SDP file %1: payload type %2 is not a dynamic one (96 to 127)</source>
        <translation>SDP-Datei %1: Payload-Typ %2 ist nicht dynamisch (96 bis 127)</translation>
    </message>
    <message>
        <source>SDP file %1: no rtpmap for payload %2</source>
        <translation>SDP-Datei %1: kein rtpmap für Payload %2</translation>
    </message>
    <message>
        <source>SDP file %1: the video is %2, not H.264 or H.265</source>
        <translation>SDP-Datei %1: das Video ist %2, nicht H.264 oder H.265</translation>
    </message>
    <message>
        <source>SDP file %1 describes no video</source>
        <translation>SDP-Datei %1 beschreibt kein Video</translation>
    </message>
</context>
<context>
    <name>WaypointAction</name>
    <message>
        <source>Wait for operator</source>
        <translation>Auf Bediener warten</translation>
    </message>
    <message>
        <source>Wait %1 s</source>
        <translation>%1 s warten</translation>
    </message>
    <message>
        <source>Heading %1°%2</source>
        <translation>Kurs %1°%2</translation>
    </message>
    <message>
        <source> from course</source>
        <translation> relativ zur Flugrichtung</translation>
    </message>
    <message>
        <source>Look at %1, %2</source>
        <translation>Ausrichten auf %1, %2</translation>
    </message>
    <message>
        <source>Take photo</source>
        <translation>Foto aufnehmen</translation>
    </message>
    <message>
        <source>Start video</source>
        <translation>Video starten</translation>
    </message>
    <message>
        <source>Stop video</source>
        <translation>Video stoppen</translation>
    </message>
    <message>
        <source>Toggle video</source>
        <translation>Video umschalten</translation>
    </message>
    <message>
        <source>Photo every %1 s</source>
        <translation>Foto alle %1 s</translation>
    </message>
    <message>
        <source>Photo every %1 m</source>
        <translation>Foto alle %1 m</translation>
    </message>
    <message>
        <source>Stop photos</source>
        <translation>Fotos stoppen</translation>
    </message>
    <message>
        <source>Panorama %1°</source>
        <translation>Panorama %1°</translation>
    </message>
    <message>
        <source>tilt %1°</source>
        <translation>Neigung %1°</translation>
    </message>
    <message>
        <source>roll %1°</source>
        <translation>Rollen %1°</translation>
    </message>
    <message>
        <source>yaw %1°</source>
        <translation>Gieren %1°</translation>
    </message>
    <message>
        <source>zoom %1</source>
        <translation>Zoom %1</translation>
    </message>
    <message>
        <source>Gimbal (nothing set)</source>
        <translation>Gimbal (nichts gesetzt)</translation>
    </message>
</context>
<context>
    <name>WaypointTable</name>
    <message numerus="yes">
        <source>%n selected:</source>
        <translation>
            <numerusform>%n ausgewählt:</numerusform>
            <numerusform>%n ausgewählt:</numerusform>
        </translation>
    </message>
    <message>
        <source>alt m</source>
        <translation>Höhe m</translation>
    </message>
    <message>
        <source>Set</source>
        <translation>Setzen</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>Altitude above ground (AGL) or above mean sea level (AMSL)</source>
        <translation>Höhe über Grund (AGL) oder über dem mittleren Meeresspiegel (AMSL)</translation>
    </message>
    <message>
        <source>Heights:</source>
        <translation>Höhen:</translation>
    </message>
    <message>
        <source>as set</source>
        <translation>wie gesetzt</translation>
    </message>
    <message>
        <source>all AMSL</source>
        <translation>alle AMSL</translation>
    </message>
    <message>
        <source>all AGL</source>
        <translation>alle AGL</translation>
    </message>
    <message>
        <source>AMSL and AGL are converted through the ground under each waypoint</source>
        <translation>AMSL und AGL werden über das Gelände unter jedem Wegpunkt umgerechnet</translation>
    </message>
    <message>
        <source>ground: %1</source>
        <translation>Gelände: %1</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>Latitude</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Alt</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <source>AMSL</source>
        <translation>AMSL</translation>
    </message>
    <message>
        <source>AGL</source>
        <translation>AGL</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Ground</source>
        <translation>Gelände</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschw.</translation>
    </message>
    <message>
        <source>Actions</source>
        <translation>Aktionen</translation>
    </message>
    <message>
        <source>Area scan</source>
        <translation>Flächenscan</translation>
    </message>
</context>
<context>
    <name>WplFormat</name>
    <message>
        <source>not a waypoint file: expected &quot;QGC WPL 110&quot;, found &quot;%1&quot;</source>
        <translation>keine Wegpunktdatei: „QGC WPL 110“ erwartet, gefunden: „%1“</translation>
    </message>
    <message>
        <source>unsupported waypoint file version &quot;%1&quot;; Sortie reads QGC WPL 110</source>
        <translation>nicht unterstützte Version der Wegpunktdatei „%1“; Sortie liest QGC WPL 110</translation>
    </message>
    <message>
        <source>expected 12 tab-separated fields, found %1</source>
        <translation>12 durch Tabulatoren getrennte Felder erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>field %1 (%2) is not a number: &quot;%3&quot;</source>
        <translation>Feld %1 (%2) ist keine Zahl: „%3“</translation>
    </message>
    <message>
        <source>field %1 (%2) must be a whole number, found %3</source>
        <translation>Feld %1 (%2) muss eine ganze Zahl sein, gefunden: %3</translation>
    </message>
    <message>
        <source>item %1 where item %2 was expected</source>
        <translation>Element %1, wo Element %2 erwartet wurde</translation>
    </message>
    <message>
        <source>the home position %1, %2 is not a position</source>
        <translation>die Home-Position %1, %2 ist keine Position</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>die Datei ist leer</translation>
    </message>
    <message>
        <source>the file has no items, not even the home position</source>
        <translation>die Datei hat keine Elemente, nicht einmal die Home-Position</translation>
    </message>
    <message>
        <source>The route has no home position: the first point was written as home, at 0 m AMSL.</source>
        <translation>Die Route hat keine Home-Position: Der erste Punkt wurde als Home-Punkt geschrieben, auf 0 m AMSL.</translation>
    </message>
</context>
<context>
    <name>WpmlDocumentReader</name>
    <message>
        <source>malformed XML: %1</source>
        <translation>fehlerhaftes XML: %1</translation>
    </message>
    <message>
        <source>%1 is not a number: &quot;%2&quot;</source>
        <translation>%1 ist keine Zahl: „%2“</translation>
    </message>
    <message>
        <source>%1 is not a whole number: &quot;%2&quot;</source>
        <translation>%1 ist keine ganze Zahl: „%2“</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; (written as &quot;%3&quot;)</source>
        <translation>%1 „%2“ (geschrieben als „%3“)</translation>
    </message>
    <message>
        <source>coordinates &quot;%1&quot; are not longitude,latitude in degrees</source>
        <translation>Koordinaten „%1“ sind nicht Länge,Breite in Grad</translation>
    </message>
    <message>
        <source>a waypoint index is not a whole number</source>
        <translation>ein Wegpunktindex ist keine ganze Zahl</translation>
    </message>
</context>
<context>
    <name>ZipArchive</name>
    <message>
        <source>two of its entries have the same name</source>
        <translation>zwei seiner Einträge haben denselben Namen</translation>
    </message>
    <message>
        <source>its directory and its entries disagree</source>
        <translation>sein Verzeichnis und seine Einträge stimmen nicht überein</translation>
    </message>
    <message>
        <source>it has no ZIP directory (truncated, or not a ZIP file)</source>
        <translation>es hat kein ZIP-Verzeichnis (abgeschnitten oder keine ZIP-Datei)</translation>
    </message>
    <message>
        <source>the archive has no end of central directory</source>
        <translation>das Archiv hat kein Ende des zentralen Verzeichnisses</translation>
    </message>
    <message>
        <source>ZIP64 archives are not read</source>
        <translation>ZIP64-Archive werden nicht gelesen</translation>
    </message>
    <message>
        <source>a central directory record is damaged at byte %1</source>
        <translation>ein Eintrag des zentralen Verzeichnisses ist bei Byte %1 beschädigt</translation>
    </message>
    <message>
        <source>an entry&apos;s local header lies outside the archive</source>
        <translation>der lokale Header eines Eintrags liegt außerhalb des Archivs</translation>
    </message>
    <message>
        <source>the entries &quot;%1&quot; and &quot;%2&quot; share bytes in the archive (a ZIP bomb&apos;s trick): not read</source>
        <translation>die Einträge „%1“ und „%2“ teilen sich Bytes im Archiv (der Trick einer ZIP-Bombe): nicht gelesen</translation>
    </message>
    <message>
        <source>not a ZIP archive: %1</source>
        <translation>kein ZIP-Archiv: %1</translation>
    </message>
    <message>
        <source>not a readable ZIP archive: %1</source>
        <translation>kein lesbares ZIP-Archiv: %1</translation>
    </message>
    <message>
        <source>the archive lists %1 entries, more than the %2 read</source>
        <translation>das Archiv listet %1 Einträge, mehr als die %2 gelesenen</translation>
    </message>
    <message>
        <source>the central directory lists %1 entries where libzip read %2</source>
        <translation>das zentrale Verzeichnis listet %1 Einträge, wo libzip %2 gelesen hat</translation>
    </message>
    <message>
        <source>the archive has no &quot;%1&quot;</source>
        <translation>das Archiv hat kein „%1“</translation>
    </message>
    <message>
        <source>&quot;%1&quot; would inflate to %2 bytes, more than the %3 read from one entry</source>
        <translation>„%1“ würde auf %2 Bytes entpackt, mehr als die %3, die pro Eintrag gelesen werden</translation>
    </message>
    <message>
        <source>reading &quot;%1&quot; would inflate the archive past %2 bytes in all</source>
        <translation>das Lesen von „%1“ würde das Archiv auf insgesamt mehr als %2 Bytes entpacken</translation>
    </message>
    <message>
        <source>&quot;%1&quot; claims %2 bytes from %3 compressed, more than %4 times: not inflated</source>
        <translation>„%1“ gibt %2 Bytes aus %3 komprimierten an, mehr als das %4-Fache: nicht entpackt</translation>
    </message>
    <message>
        <source>&quot;%1&quot; cannot be read: %2</source>
        <translation>„%1“ kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is damaged: %2</source>
        <translation>„%1“ ist beschädigt: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; holds a different size than the archive says (%2 bytes)</source>
        <translation>„%1“ hat eine andere Größe, als das Archiv angibt (%2 Bytes)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is damaged (its CRC does not match)</source>
        <translation>„%1“ ist beschädigt (die CRC stimmt nicht)</translation>
    </message>
    <message>
        <source>the archive could not be written: %1</source>
        <translation>das Archiv konnte nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <source>the archive could not be written: its bytes could not be read back</source>
        <translation>das Archiv konnte nicht geschrieben werden: Seine Bytes konnten nicht zurückgelesen werden</translation>
    </message>
</context>
<context>
    <name>Zone</name>
    <message>
        <source>above home</source>
        <translation>über dem Home-Punkt</translation>
    </message>
    <message>
        <source>server aerodrome</source>
        <translation>Server-Flugplatzzone</translation>
    </message>
    <message>
        <source>server custom</source>
        <translation>eigene Serverzone</translation>
    </message>
    <message>
        <source>vehicle fence</source>
        <translation>Fahrzeug-Geofence</translation>
    </message>
    <message>
        <source>%1 polygon %2</source>
        <translation>%1, Polygon %2</translation>
    </message>
    <message>
        <source>%1 circle %2</source>
        <translation>%1, Kreis %2</translation>
    </message>
</context>
<context>
    <name>ZoneEditor</name>
    <message>
        <source>drawn on the map</source>
        <translation>auf der Karte gezeichnet</translation>
    </message>
    <message>
        <source>vertex %1</source>
        <translation>Ecke %1</translation>
    </message>
</context>
<context>
    <name>ZoneFiles</name>
    <message>
        <source>%1 was left out: %2</source>
        <translation>%1 wurde ausgelassen: %2</translation>
    </message>
    <message>
        <source>unknown zone file type &quot;.%1&quot; (Sortie reads .plan, .geojson, .json and .kml)</source>
        <translation>unbekannter Zonendateityp „.%1“ (Sortie liest .plan, .geojson, .json und .kml)</translation>
    </message>
    <message>
        <source>volume %1: %2</source>
        <translation>Volumen %1: %2</translation>
    </message>
    <message>
        <source>%1 zone %2 (&apos;%3&apos;) was left out: %4</source>
        <translation>%1-Zone %2 („%3“) wurde ausgelassen: %4</translation>
    </message>
</context>
<context>
    <name>ZoneLegend</name>
    <message>
        <source>Prohibited</source>
        <translation>Verboten</translation>
    </message>
    <message>
        <source>Authorisation needed</source>
        <translation>Genehmigung nötig</translation>
    </message>
    <message>
        <source>Conditions apply</source>
        <translation>Mit Auflagen</translation>
    </message>
    <message>
        <source>Information only</source>
        <translation>Nur Information</translation>
    </message>
    <message>
        <source>Not in force during the flight</source>
        <translation>Während des Flugs nicht in Kraft</translation>
    </message>
</context>
<context>
    <name>ZonePanel</name>
    <message>
        <source>Load zones</source>
        <translation>Zonen laden</translation>
    </message>
    <message>
        <source>Zones (*.geojson *.json *.kml *.plan)</source>
        <translation>Zonen (*.geojson *.json *.kml *.plan)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Zones (%1)</source>
        <translation>Zonen (%1)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Laden…</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>Polygon</translation>
    </message>
    <message>
        <source>Click the corners on the map, then Create</source>
        <translation>Ecken auf der Karte anklicken, dann Erstellen</translation>
    </message>
    <message>
        <source>Circle</source>
        <translation>Kreis</translation>
    </message>
    <message>
        <source>Click the centre on the map; drag its handle for the radius</source>
        <translation>Mittelpunkt auf der Karte anklicken; den Griff ziehen, um den Radius einzustellen</translation>
    </message>
    <message>
        <source>%1 corners</source>
        <translation>%1 Ecken</translation>
    </message>
    <message>
        <source>Create</source>
        <translation>Erstellen</translation>
    </message>
    <message>
        <source>Checked against the route when ticked</source>
        <translation>Wird bei Haken gegen die Route geprüft</translation>
    </message>
    <message>
        <source>%1 · %2 – %3</source>
        <translation>%1 · %2 – %3</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>Floor (m)</source>
        <translation>Untergrenze (m)</translation>
    </message>
    <message>
        <source>ground</source>
        <translation>Boden</translation>
    </message>
    <message>
        <source>Ceiling (m)</source>
        <translation>Obergrenze (m)</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>unbegrenzt</translation>
    </message>
    <message>
        <source>Above</source>
        <translation>Bezug</translation>
    </message>
    <message>
        <source>Remove zone</source>
        <translation>Zone entfernen</translation>
    </message>
    <message>
        <source>Warn within (m)</source>
        <translation>Warnen innerhalb (m)</translation>
    </message>
    <message>
        <source>exclusion</source>
        <translation>Ausschluss</translation>
    </message>
    <message>
        <source>inclusion</source>
        <translation>Einschluss</translation>
    </message>
    <message>
        <source>HOME</source>
        <translation>Home-Punkt</translation>
    </message>
    <message>
        <source>Discard copy</source>
        <translation>Kopie verwerfen</translation>
    </message>
    <message>
        <source>The server&apos;s zone stays as it is</source>
        <translation>Die Zone des Servers bleibt, wie sie ist</translation>
    </message>
    <message>
        <source>Update on server</source>
        <translation>Auf dem Server aktualisieren</translation>
    </message>
    <message>
        <source>Send to server</source>
        <translation>An den Server senden</translation>
    </message>
    <message>
        <source>Edit here</source>
        <translation>Hier bearbeiten</translation>
    </message>
    <message>
        <source>Draw a copy to edit; Update on server stores it</source>
        <translation>Eine Kopie zum Bearbeiten zeichnen; „Auf dem Server aktualisieren“ speichert sie</translation>
    </message>
    <message>
        <source>Delete on server</source>
        <translation>Auf dem Server löschen</translation>
    </message>
    <message>
        <source>Waiting for the server…</source>
        <translation>Warten auf den Server…</translation>
    </message>
    <message>
        <source>Delete zone</source>
        <translation>Zone löschen</translation>
    </message>
    <message>
        <source>Delete &apos;%1&apos; on the server, for every operator?</source>
        <translation>„%1“ auf dem Server löschen, für alle Bediener?</translation>
    </message>
    <message>
        <source>Zone feed URL (https://…)</source>
        <translation>URL des Zonen-Feeds (https://…)</translation>
    </message>
    <message>
        <source>Fetching…</source>
        <translation>Wird abgerufen…</translation>
    </message>
    <message>
        <source>Fetch</source>
        <translation>Abrufen</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Aktualisieren</translation>
    </message>
    <message>
        <source>Fetch the zone feed again from %1</source>
        <translation>Den Zonen-Feed erneut von %1 abrufen</translation>
    </message>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>Authorisation reference</source>
        <translation>Genehmigungsnummer</translation>
    </message>
    <message>
        <source>Change</source>
        <translation>Ändern</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Eintragen</translation>
    </message>
    <message>
        <source>Kept with the route; the check then warns instead of refusing (empty: removed)</source>
        <translation>Wird mit der Route gespeichert; die Prüfung warnt dann, statt abzulehnen (leer: entfernt)</translation>
    </message>
</context>
<context>
    <name>sortie</name>
    <message>
        <source>Sortie: mission planning and live telemetry for UgCS servers and VCI vehicles.</source>
        <translation>Sortie: Missionsplanung und Live-Telemetrie für UgCS-Server und VCI-Fahrzeuge.</translation>
    </message>
    <message>
        <source>Start the built-in simulator on this computer and connect to it.</source>
        <translation>Den eingebauten Simulator auf diesem Computer starten und sich mit ihm verbinden.</translation>
    </message>
    <message>
        <source>User name to log in with.</source>
        <translation>Benutzername für die Anmeldung.</translation>
    </message>
    <message>
        <source>Print the start-up time and memory in use, then quit (for benchmarks).</source>
        <translation>Startzeit und belegten Speicher ausgeben, dann beenden (für Benchmarks).</translation>
    </message>
    <message>
        <source>Folder for autosaved edits (default: the application data folder; also SORTIE_AUTOSAVE_DIR).</source>
        <translation>Ordner für automatisch gesicherte Änderungen (Standard: der Anwendungsdatenordner; auch SORTIE_AUTOSAVE_DIR).</translation>
    </message>
    <message>
        <source>An ADS-B receiver&apos;s SBS-1 feed for manned traffic, as dump1090 serves it (port 30003); also the setting traffic/sbsAddress.</source>
        <translation>SBS-1-Feed eines ADS-B-Empfängers für bemannten Verkehr, wie ihn dump1090 liefert (Port 30003); auch die Einstellung traffic/sbsAddress.</translation>
    </message>
    <message>
        <source>--demo with only the server&apos;s three vehicles: &quot;parked&quot; (nothing moves) or &quot;flying&quot; (one flies, followed in the fly view); for benchmarks.</source>
        <translation>--demo nur mit den drei Fahrzeugen des Servers: „parked“ (nichts bewegt sich) oder „flying“ (eines fliegt und wird in der Flugansicht verfolgt); für Benchmarks.</translation>
    </message>
    <message>
        <source>A DEM for the terrain: any raster GDAL reads (GeoTIFF, COG, Copernicus DEM, .hgt, ...) or a folder of them, asked before the server (also the setting terrain/demFolder).</source>
        <translation>Ein DEM für das Gelände: jedes Raster, das GDAL liest (GeoTIFF, COG, Copernicus DEM, .hgt, ...), oder ein Ordner davon; wird vor dem Server gefragt (auch die Einstellung terrain/demFolder).</translation>
    </message>
    <message>
        <source>UgCS server to connect to: host:port, or tls://host:port over TLS (a server behind a TLS terminator).</source>
        <translation>UgCS-Server, mit dem verbunden wird: host:port, oder tls://host:port über TLS (ein Server hinter einem TLS-Terminator).</translation>
    </message>
    <message>
        <source>With --server tls://: the only certificate the server may show, as its SHA-256 fingerprint or a PEM file; remembered for that server.</source>
        <translation>Mit --server tls://: das einzige Zertifikat, das der Server zeigen darf, als SHA-256-Fingerabdruck oder PEM-Datei; für diesen Server gespeichert.</translation>
    </message>
    <message>
        <source>Connect a vehicle directly over VCI: tcp://host:port, vci+tls://host:port[?sha256=FINGERPRINT] or serial:///dev/ttyX?baud=57600.</source>
        <translation>Ein Fahrzeug direkt über VCI verbinden: tcp://host:port, vci+tls://host:port[?sha256=FINGERABDRUCK] oder serial:///dev/ttyX?baud=57600.</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::Airspace</name>
    <message>
        <source>Reason: %1</source>
        <translation>Grund: %1</translation>
    </message>
    <message>
        <source>When: %1</source>
        <translation>Wann: %1</translation>
    </message>
    <message>
        <source>Not in force during the planned flight.</source>
        <translation>Während des geplanten Flugs nicht in Kraft.</translation>
    </message>
    <message>
        <source>Authority: %1</source>
        <translation>Behörde: %1</translation>
    </message>
    <message>
        <source>%1: fetched from %2 %3</source>
        <translation>%1: von %2 abgerufen, %3</translation>
    </message>
    <message>
        <source>%1: a file changed %2</source>
        <translation>%1: eine Datei, geändert %2</translation>
    </message>
    <message>
        <source>Some zone data is older than a week: fetch it or load it again before you fly.</source>
        <translation>Einige Zonendaten sind älter als eine Woche: rufen Sie sie ab oder laden Sie sie vor dem Flug neu.</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ServerZones</name>
    <message>
        <source>Zones across the ±180° meridian are not supported; the view was not asked about.</source>
        <translation>Zonen über den Meridian ±180° hinweg werden nicht unterstützt; für diesen Ausschnitt wurde nicht angefragt.</translation>
    </message>
    <message>
        <source>The server&apos;s no-fly zones could not be read: %1</source>
        <translation>Die Flugverbotszonen des Servers konnten nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not saved: not connected to the server.</source>
        <translation>Zone „%1“ wurde nicht gespeichert: keine Verbindung zum Server.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; cannot be saved on the server: %2.</source>
        <translation>Zone „%1“ kann nicht auf dem Server gespeichert werden: %2.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not saved: %2</source>
        <translation>Zone „%1“ wurde nicht gespeichert: %2</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not saved: it is locked (%2)</source>
        <translation>Zone „%1“ wurde nicht gespeichert: Sie ist gesperrt (%2)</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was saved, but the server&apos;s answer cannot be read back: %2</source>
        <translation>Zone „%1“ wurde gespeichert, aber die Antwort des Servers kann nicht zurückgelesen werden: %2</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: it is not on the server.</source>
        <translation>Zone „%1“ wurde nicht gelöscht: nicht auf dem Server vorhanden.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: aerodrome zones are the server&apos;s own.</source>
        <translation>Zone „%1“ wurde nicht gelöscht: Flugplatzzonen gehören dem Server.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: not connected to the server.</source>
        <translation>Zone „%1“ wurde nicht gelöscht: keine Verbindung zum Server.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: it is locked (%2)</source>
        <translation>Zone „%1“ wurde nicht gelöscht: gesperrt (%2)</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: %2</source>
        <translation>Zone „%1“ wurde nicht gelöscht: %2</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneAlertMonitor</name>
    <message>
        <source>%1 is inside &apos;%2&apos;</source>
        <translation>%1 ist in „%2“</translation>
    </message>
    <message>
        <source>%1 enters &apos;%2&apos;%3</source>
        <translation>%1 fliegt in „%2“ ein%3</translation>
    </message>
    <message>
        <source>%1 is outside &apos;%2&apos;</source>
        <translation>%1 ist außerhalb von „%2“</translation>
    </message>
    <message>
        <source>%1 leaves &apos;%2&apos;%3</source>
        <translation>%1 verlässt „%2“%3</translation>
    </message>
    <message>
        <source> (its height there is unknown)</source>
        <translation> (seine Höhe dort ist unbekannt)</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneEditor</name>
    <message>
        <source>A zone needs at least three corners.</source>
        <translation>Eine Zone braucht mindestens drei Ecken.</translation>
    </message>
    <message>
        <source>This polygon cannot be a zone: %1</source>
        <translation>Dieses Polygon kann keine Zone sein: %1</translation>
    </message>
    <message>
        <source>Draw zone</source>
        <translation>Zone zeichnen</translation>
    </message>
    <message>
        <source>A circular zone needs a centre and a radius above 0 m.</source>
        <translation>Eine Kreiszone braucht einen Mittelpunkt und einen Radius über 0 m.</translation>
    </message>
    <message>
        <source>Draw circular zone</source>
        <translation>Kreiszone zeichnen</translation>
    </message>
    <message>
        <source>There is no drawn zone %1.</source>
        <translation>Es gibt keine gezeichnete Zone %1.</translation>
    </message>
    <message>
        <source>Remove zone</source>
        <translation>Zone entfernen</translation>
    </message>
    <message>
        <source>That is not a position.</source>
        <translation>Das ist keine Position.</translation>
    </message>
    <message>
        <source>A circle has only its centre to move.</source>
        <translation>Bei einem Kreis lässt sich nur der Mittelpunkt verschieben.</translation>
    </message>
    <message>
        <source>The zone has no corner %1.</source>
        <translation>Die Zone hat keine Ecke %1.</translation>
    </message>
    <message>
        <source>Move zone corner</source>
        <translation>Zonenecke verschieben</translation>
    </message>
    <message>
        <source>A corner can be added only to a polygon, on one of its edges.</source>
        <translation>Eine Ecke kann nur einem Polygon hinzugefügt werden, auf einer seiner Kanten.</translation>
    </message>
    <message>
        <source>Add zone corner</source>
        <translation>Zonenecke hinzufügen</translation>
    </message>
    <message>
        <source>A zone keeps at least three corners.</source>
        <translation>Eine Zone behält mindestens drei Ecken.</translation>
    </message>
    <message>
        <source>Remove zone corner</source>
        <translation>Zonenecke entfernen</translation>
    </message>
    <message>
        <source>The radius must be above 0 m.</source>
        <translation>Der Radius muss über 0 m liegen.</translation>
    </message>
    <message>
        <source>Only a circular zone has a radius.</source>
        <translation>Nur eine Kreiszone hat einen Radius.</translation>
    </message>
    <message>
        <source>Zone radius</source>
        <translation>Zonenradius</translation>
    </message>
    <message>
        <source>A zone needs a name.</source>
        <translation>Eine Zone braucht einen Namen.</translation>
    </message>
    <message>
        <source>Rename zone</source>
        <translation>Zone umbenennen</translation>
    </message>
    <message>
        <source>A zone is an exclusion or an inclusion zone, not &quot;%1&quot;.</source>
        <translation>Eine Zone ist eine Ausschluss- oder Einschlusszone (exclusion/inclusion), nicht „%1“.</translation>
    </message>
    <message>
        <source>Zone kind</source>
        <translation>Zonenart</translation>
    </message>
    <message>
        <source>Heights are AMSL, AGL or HOME, not &quot;%1&quot;.</source>
        <translation>Höhen sind AMSL, AGL oder HOME, nicht „%1“.</translation>
    </message>
    <message>
        <source>A floor or ceiling is a number of metres, or empty.</source>
        <translation>Eine Unter- oder Obergrenze ist eine Zahl in Metern oder leer.</translation>
    </message>
    <message>
        <source>The ceiling (%1 m) must be above the floor (%2 m).</source>
        <translation>Die Obergrenze (%1 m) muss über der Untergrenze (%2 m) liegen.</translation>
    </message>
    <message>
        <source>Zone floor and ceiling</source>
        <translation>Unter- und Obergrenze der Zone</translation>
    </message>
    <message>
        <source>The zone would not be a valid polygon: %1</source>
        <translation>Die Zone wäre kein gültiges Polygon: %1</translation>
    </message>
    <message>
        <source>Zone %1</source>
        <translation>Zone %1</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneFeed</name>
    <message>
        <source>Another zone feed is being fetched.</source>
        <translation>Ein anderer Zonen-Feed wird gerade abgerufen.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no web address (http:// or https://).</source>
        <translation>„%1“ ist keine Webadresse (http:// oder https://).</translation>
    </message>
    <message>
        <source>There is no folder to keep the zone feed in (%1).</source>
        <translation>Es gibt keinen Ordner für den Zonen-Feed (%1).</translation>
    </message>
    <message>
        <source>The zone feed is larger than %1 MiB; it was not kept.</source>
        <translation>Der Zonen-Feed ist größer als %1 MiB; er wurde nicht gespeichert.</translation>
    </message>
    <message>
        <source>The zone feed&apos;s fetch was stopped (cancelled, or no answer for %1 s).</source>
        <translation>Der Abruf des Zonen-Feeds wurde beendet (abgebrochen oder %1 s keine Antwort).</translation>
    </message>
    <message>
        <source>The zone feed&apos;s server answered HTTP %1.</source>
        <translation>Der Server des Zonen-Feeds antwortete mit HTTP %1.</translation>
    </message>
    <message>
        <source>The zone feed cannot be fetched: %1.</source>
        <translation>Der Zonen-Feed kann nicht abgerufen werden: %1.</translation>
    </message>
    <message>
        <source>The zone feed&apos;s server sent nothing.</source>
        <translation>Der Server des Zonen-Feeds hat nichts gesendet.</translation>
    </message>
    <message>
        <source>The zone feed cannot be kept in %1: %2.</source>
        <translation>Der Zonen-Feed kann nicht in %1 gespeichert werden: %2.</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneSharing</name>
    <message>
        <source>Wait: the server has not answered the last change yet.</source>
        <translation>Bitte warten: Der Server hat auf die letzte Änderung noch nicht geantwortet.</translation>
    </message>
    <message>
        <source>Only a zone drawn here can be sent to the server.</source>
        <translation>Nur eine hier gezeichnete Zone kann an den Server gesendet werden.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was changed on the server since you copied it (version %2, now %3). Remove your copy and edit the server&apos;s zone again.</source>
        <translation>Zone „%1“ wurde auf dem Server geändert, seit Sie sie kopiert haben (Version %2, jetzt %3). Entfernen Sie Ihre Kopie und bearbeiten Sie die Zone des Servers erneut.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; is on the server; you changed it since sending, so your copy stays.</source>
        <translation>Zone „%1“ ist auf dem Server; Sie haben sie seit dem Senden geändert, daher bleibt Ihre Kopie.</translation>
    </message>
    <message>
        <source>Send zone &apos;%1&apos; to the server</source>
        <translation>Zone „%1“ an den Server senden</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; is on the server.</source>
        <translation>Zone „%1“ ist auf dem Server.</translation>
    </message>
    <message>
        <source>Only the server&apos;s custom zones can be edited here; aerodrome zones are the server&apos;s own.</source>
        <translation>Nur die eigenen Zonen des Servers können hier bearbeitet werden; Flugplatzzonen gehören dem Server.</translation>
    </message>
    <message>
        <source>Edit server zone &apos;%1&apos;</source>
        <translation>Serverzone „%1“ bearbeiten</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; is drawn here to edit; send it to store the change on the server.</source>
        <translation>Zone „%1“ ist hier zum Bearbeiten gezeichnet; senden Sie sie, um die Änderung auf dem Server zu speichern.</translation>
    </message>
    <message>
        <source>Only the server&apos;s custom zones can be deleted here.</source>
        <translation>Nur die eigenen Zonen des Servers können hier gelöscht werden.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was deleted on the server.</source>
        <translation>Zone „%1“ wurde auf dem Server gelöscht.</translation>
    </message>
</context>
<context>
    <name>sortie::client::AutosaveRecovery</name>
    <message>
        <source>The autosaved edits in %1 cannot be read: %2</source>
        <translation>Die automatisch gesicherten Änderungen in %1 können nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>The autosaved edits in %1 cannot be read (%2). The file was kept as %3.</source>
        <translation>Die automatisch gesicherten Änderungen in %1 können nicht gelesen werden (%2). Die Datei wurde als %3 aufbewahrt.</translation>
    </message>
    <message>
        <source>The autosaved edits in %1 cannot be read (%2).</source>
        <translation>Die automatisch gesicherten Änderungen in %1 können nicht gelesen werden (%2).</translation>
    </message>
    <message>
        <source>Untitled route</source>
        <translation>Unbenannte Route</translation>
    </message>
    <message>
        <source>route %1, version %2</source>
        <translation>Route %1, Version %2</translation>
    </message>
    <message>
        <source>, on %1</source>
        <translation>, auf %1</translation>
    </message>
    <message>
        <source> as %1</source>
        <translation> als %1</translation>
    </message>
    <message>
        <source>The route open now has unsaved edits, and restoring would replace it: save or undo them first.</source>
        <translation>Die geöffnete Route hat ungespeicherte Änderungen, und das Wiederherstellen würde sie ersetzen: Speichern Sie sie zuerst oder machen Sie sie rückgängig.</translation>
    </message>
    <message>
        <source>%1 as %2</source>
        <translation>%1 als %2</translation>
    </message>
    <message>
        <source>These edits belong to route %1 on %2, and saving them updates that route. Sign in to %2 to restore them: choose Later, sign in, and they are offered again.</source>
        <translation>Diese Änderungen gehören zu Route %1 auf %2, und ihr Speichern aktualisiert diese Route. Melden Sie sich bei %2 an, um sie wiederherzustellen: Wählen Sie Später, melden Sie sich an, dann werden sie erneut angeboten.</translation>
    </message>
    <message>
        <source>These edits belong to route %1 on %2, but this session is signed in to %3 as %4. Sign out and sign in to %2 to restore them; until then they are kept and offered again at each start.</source>
        <translation>Diese Änderungen gehören zu Route %1 auf %2, aber diese Sitzung ist bei %3 als %4 angemeldet. Melden Sie sich ab und bei %2 an, um sie wiederherzustellen; bis dahin bleiben sie erhalten und werden bei jedem Start erneut angeboten.</translation>
    </message>
    <message>
        <source>Restore autosaved edits</source>
        <translation>Automatisch gesicherte Änderungen wiederherstellen</translation>
    </message>
    <message>
        <source>The autosave %1 could not be moved aside.</source>
        <translation>Die automatische Sicherung %1 konnte nicht beiseitegelegt werden.</translation>
    </message>
</context>
<context>
    <name>sortie::client::CommandPolicy</name>
    <message>
        <source>Manual</source>
        <translation>Manuell</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Halten</translation>
    </message>
    <message>
        <source>Taking off</source>
        <translation>Startet</translation>
    </message>
    <message>
        <source>Auto (fly the mission)</source>
        <translation>Auto (Mission fliegen)</translation>
    </message>
    <message>
        <source>Guided</source>
        <translation>Geführt</translation>
    </message>
    <message>
        <source>Land</source>
        <translation>Landung</translation>
    </message>
    <message>
        <source>Return home</source>
        <translation>Rückkehr</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Unbekannt</translation>
    </message>
    <message>
        <source>the vehicle</source>
        <translation>das Fahrzeug</translation>
    </message>
    <message>
        <source>Arm %1? Its motors may start.</source>
        <translation>Soll %1 scharf geschaltet werden? Die Motoren können anlaufen.</translation>
    </message>
    <message>
        <source>Disarm %1? It may be in the air, and would fall.</source>
        <translation>Soll %1 entschärft werden? Ist es in der Luft, stürzt es ab.</translation>
    </message>
    <message>
        <source>Take off with %1 to %2 m above home?</source>
        <translation>Soll %1 auf %2 m über dem Home-Punkt starten?</translation>
    </message>
    <message numerus="yes">
        <source>Start the mission on %1 (%n waypoint(s))?</source>
        <translation>
            <numerusform>Mission auf %1 starten (%n Wegpunkt)?</numerusform>
            <numerusform>Mission auf %1 starten (%n Wegpunkte)?</numerusform>
        </translation>
    </message>
    <message>
        <source>Start the mission on %1? Sortie has not seen its mission.</source>
        <translation>Mission auf %1 starten? Sortie kennt die Mission an Bord nicht.</translation>
    </message>
    <message>
        <source>Arm</source>
        <translation>Scharf schalten</translation>
    </message>
    <message>
        <source>Disarm</source>
        <translation>Entschärfen</translation>
    </message>
    <message>
        <source>Take off</source>
        <translation>Starten</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>%1 sent despite the checklist (the operator overrode it): %2</source>
        <translation>%1 trotz der Checkliste gesendet (vom Bediener übergangen): %2</translation>
    </message>
</context>
<context>
    <name>sortie::client::ConnectionController</name>
    <message>
        <source>connection lost; attempt %1 in %2 s</source>
        <translation>Verbindung verloren; Versuch %1 in %2 s</translation>
    </message>
    <message>
        <source>reconnected in a new session</source>
        <translation>in einer neuen Sitzung wieder verbunden</translation>
    </message>
    <message>
        <source>%1 at %2</source>
        <translation>%1 bei %2</translation>
    </message>
    <message>
        <source>The server address is not usable: %1.</source>
        <translation>Die Serveradresse ist nicht verwendbar: %1.</translation>
    </message>
    <message>
        <source>Enter a user name.</source>
        <translation>Geben Sie einen Benutzernamen ein.</translation>
    </message>
    <message>
        <source>%1. Check the server&apos;s address and this computer&apos;s network.</source>
        <translation>%1. Prüfen Sie die Serveradresse und das Netzwerk dieses Computers.</translation>
    </message>
    <message>
        <source>%1. Is the UgCS server running, and is the port right?</source>
        <translation>%1. Läuft der UgCS-Server, und stimmt der Port?</translation>
    </message>
    <message>
        <source>Wrong user name or password (%1).</source>
        <translation>Falscher Benutzername oder falsches Passwort (%1).</translation>
    </message>
    <message>
        <source>%1. This server cannot be used with Sortie.</source>
        <translation>%1. Dieser Server kann nicht mit Sortie verwendet werden.</translation>
    </message>
    <message>
        <source>The server&apos;s licence allows no more connections (%1). Close another client or extend the licence.</source>
        <translation>Die Lizenz des Servers erlaubt keine weiteren Verbindungen (%1). Schließen Sie einen anderen Client oder erweitern Sie die Lizenz.</translation>
    </message>
    <message>
        <source>The server did not answer in time (%1). It may be overloaded or not a UgCS server.</source>
        <translation>Der Server hat nicht rechtzeitig geantwortet (%1). Er ist möglicherweise überlastet oder kein UgCS-Server.</translation>
    </message>
    <message>
        <source>The connection was closed (%1).</source>
        <translation>Die Verbindung wurde geschlossen (%1).</translation>
    </message>
    <message>
        <source>The server answered something Sortie cannot use (%1).</source>
        <translation>Der Server hat etwas geantwortet, das Sortie nicht verwenden kann (%1).</translation>
    </message>
    <message>
        <source>The server refused: %1</source>
        <translation>Der Server hat abgelehnt: %1</translation>
    </message>
    <message>
        <source>Disconnected</source>
        <translation>Getrennt</translation>
    </message>
    <message>
        <source>Connecting</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>Authorizing</source>
        <translation>Autorisieren</translation>
    </message>
    <message>
        <source>Logging in</source>
        <translation>Anmelden</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Bereit</translation>
    </message>
    <message>
        <source>Reconnecting</source>
        <translation>Erneut verbinden</translation>
    </message>
    <message>
        <source>%1 is not this computer, and this connection is not secured: the password for %2 would cross the network in clear, readable by anyone on the way, at every login and reconnect. Send it in clear to this server? (Choose Secure if the server is behind a TLS terminator.)</source>
        <translation>%1 ist nicht dieser Computer, und diese Verbindung ist nicht gesichert: Das Passwort für %2 ginge bei jeder Anmeldung und jedem Wiederverbinden unverschlüsselt über das Netz, lesbar für jeden unterwegs. Unverschlüsselt an diesen Server senden? (Wählen Sie „Sicher“, wenn der Server hinter einem TLS-Terminator steht.)</translation>
    </message>
    <message>
        <source>Not connected to %1: the password was not sent.</source>
        <translation>Nicht mit %1 verbunden: Das Passwort wurde nicht gesendet.</translation>
    </message>
    <message>
        <source>First secure connection to %1: its certificate is now trusted for this server and remembered. Compare its SHA-256 fingerprint with the server&apos;s: %2</source>
        <translation>Erste sichere Verbindung zu %1: Seinem Zertifikat wird für diesen Server nun vertraut, und es ist gespeichert. Vergleichen Sie seinen SHA-256-Fingerabdruck mit dem des Servers: %2</translation>
    </message>
    <message>
        <source>Secured by TLS: the certificate remembered for %1 (SHA-256 %2).</source>
        <translation>Durch TLS gesichert: das für %1 gespeicherte Zertifikat (SHA-256 %2).</translation>
    </message>
    <message>
        <source>Secured by TLS: the certificate pinned for %1 (SHA-256 %2).</source>
        <translation>Durch TLS gesichert: das für %1 festgelegte Zertifikat (SHA-256 %2).</translation>
    </message>
    <message>
        <source>Secured by TLS: a certificate this computer trusts (SHA-256 %1).</source>
        <translation>Durch TLS gesichert: ein Zertifikat, dem dieser Computer vertraut (SHA-256 %1).</translation>
    </message>
    <message>
        <source>%1. The password was not sent.</source>
        <translation>%1. Das Passwort wurde nicht gesendet.</translation>
    </message>
</context>
<context>
    <name>sortie::client::FleetRoutes</name>
    <message>
        <source>Unnamed route</source>
        <translation>Unbenannte Route</translation>
    </message>
    <message>
        <source>planned</source>
        <translation>geplant</translation>
    </message>
    <message>
        <source>uploaded %1</source>
        <translation>hochgeladen %1</translation>
    </message>
    <message>
        <source>paused: waypoint %1 of %2</source>
        <translation>pausiert: Wegpunkt %1 von %2</translation>
    </message>
    <message>
        <source>flying: waypoint %1 of %2</source>
        <translation>fliegt: Wegpunkt %1 von %2</translation>
    </message>
    <message>
        <source>flown</source>
        <translation>geflogen</translation>
    </message>
</context>
<context>
    <name>sortie::client::MissionController</name>
    <message>
        <source>Reading the server&apos;s routes</source>
        <translation>Routen des Servers werden gelesen</translation>
    </message>
    <message>
        <source>The server&apos;s routes could not be read: %1</source>
        <translation>Die Routen des Servers konnten nicht gelesen werden: %1</translation>
    </message>
    <message numerus="yes">
        <source>%1%n segment(s)</source>
        <translation>
            <numerusform>%1%n Segment</numerusform>
            <numerusform>%1%n Segmente</numerusform>
        </translation>
    </message>
    <message>
        <source>Reading the server&apos;s vehicles</source>
        <translation>Fahrzeuge des Servers werden gelesen</translation>
    </message>
    <message>
        <source>Opening the route</source>
        <translation>Route wird geöffnet</translation>
    </message>
    <message>
        <source>The route could not be opened: %1</source>
        <translation>Die Route konnte nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>The route cannot be edited here: %1</source>
        <translation>Die Route kann hier nicht bearbeitet werden: %1</translation>
    </message>
    <message>
        <source>Opened %1 (version %2).</source>
        <translation>%1 geöffnet (Version %2).</translation>
    </message>
    <message>
        <source>Not connected: your edits are kept; save again when the connection is back.</source>
        <translation>Keine Verbindung: Ihre Änderungen bleiben erhalten; speichern Sie erneut, wenn die Verbindung wieder besteht.</translation>
    </message>
    <message>
        <source>Wait until %1 is done.</source>
        <translation>Bitte warten, bis der laufende Vorgang abgeschlossen ist: %1.</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>Nicht gespeichert: %1</translation>
    </message>
    <message>
        <source>Saving</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Locking the route</source>
        <translation>Route wird gesperrt</translation>
    </message>
    <message>
        <source>Not saved: the route is locked (%1).</source>
        <translation>Nicht gespeichert: Die Route ist gesperrt (%1).</translation>
    </message>
    <message>
        <source>Reading the server&apos;s copy</source>
        <translation>Fassung des Servers wird gelesen</translation>
    </message>
    <message>
        <source>Someone else saved this route on the server (version %1) after you opened it (version %2).</source>
        <translation>Jemand anderes hat diese Route auf dem Server gespeichert (Version %1), nachdem Sie sie geöffnet haben (Version %2).</translation>
    </message>
    <message>
        <source>Saved, but the server&apos;s answer cannot be read back: %1</source>
        <translation>Gespeichert, aber die Antwort des Servers kann nicht zurückgelesen werden: %1</translation>
    </message>
    <message>
        <source>Saved %1 (version %2).</source>
        <translation>%1 gespeichert (Version %2).</translation>
    </message>
    <message>
        <source>Take the server&apos;s version</source>
        <translation>Fassung des Servers übernehmen</translation>
    </message>
    <message>
        <source>This is the server&apos;s copy now. Undo brings your edits back.</source>
        <translation>Dies ist jetzt die Fassung des Servers. Rückgängig holt Ihre Änderungen zurück.</translation>
    </message>
    <message>
        <source>This route was deleted on the server. Your copy stays open.</source>
        <translation>Diese Route wurde auf dem Server gelöscht. Ihre Kopie bleibt geöffnet.</translation>
    </message>
    <message>
        <source>Updated from the server (version %1).</source>
        <translation>Vom Server aktualisiert (Version %1).</translation>
    </message>
    <message>
        <source>Someone else saved this route on the server (version %1) while you were editing it.</source>
        <translation>Jemand anderes hat diese Route auf dem Server gespeichert (Version %1), während Sie sie bearbeitet haben.</translation>
    </message>
    <message>
        <source>The new route</source>
        <translation>Die neue Route</translation>
    </message>
    <message>
        <source>&quot;%1&quot;</source>
        <translation>„%1“</translation>
    </message>
    <message>
        <source>%1 has unsaved edits. Opening it again reads the server&apos;s copy. Save your edits first?</source>
        <translation>%1 hat ungespeicherte Änderungen. Erneutes Öffnen liest die Kopie des Servers. Die Änderungen zuerst speichern?</translation>
    </message>
    <message>
        <source>%1 has unsaved edits. Save them before opening &quot;%2&quot;?</source>
        <translation>%1 hat ungespeicherte Änderungen. Vor dem Öffnen von „%2“ speichern?</translation>
    </message>
    <message>
        <source>If you discard them, Undo brings them back.</source>
        <translation>Wenn Sie sie verwerfen, holt Rückgängig sie zurück.</translation>
    </message>
    <message>
        <source>the new route</source>
        <translation>der neuen Route</translation>
    </message>
    <message>
        <source>Open %1</source>
        <translation>%1 öffnen</translation>
    </message>
    <message>
        <source>Undo brings back your unsaved edits of %1.</source>
        <translation>Rückgängig holt Ihre ungespeicherten Änderungen an %1 zurück.</translation>
    </message>
    <message>
        <source>Not saved: another route was opened meanwhile.</source>
        <translation>Nicht gespeichert: Inzwischen wurde eine andere Route geöffnet.</translation>
    </message>
    <message>
        <source>Edits made while saving</source>
        <translation>Änderungen während des Speicherns</translation>
    </message>
    <message>
        <source>The edits you made while it was saving are kept, not saved yet.</source>
        <translation>Die Änderungen, die Sie während des Speicherns gemacht haben, bleiben erhalten, sind aber noch nicht gespeichert.</translation>
    </message>
    <message>
        <source>Update from the server (version %1)</source>
        <translation>Aktualisierung vom Server (Version %1)</translation>
    </message>
</context>
<context>
    <name>sortie::client::MissionUploader</name>
    <message>
        <source>Checking the route</source>
        <translation>Route wird geprüft</translation>
    </message>
    <message>
        <source>Waiting for your answer</source>
        <translation>Warten auf Ihre Antwort</translation>
    </message>
    <message>
        <source>Processing for %1</source>
        <translation>Verarbeitung für %1</translation>
    </message>
    <message>
        <source>Taking control of %1</source>
        <translation>Kontrolle über %1 wird übernommen</translation>
    </message>
    <message>
        <source>Uploading to %1</source>
        <translation>Hochladen auf %1</translation>
    </message>
    <message>
        <source>Releasing %1</source>
        <translation>%1 wird freigegeben</translation>
    </message>
    <message>
        <source>Reading the mission back from %1</source>
        <translation>Mission wird von %1 zurückgelesen</translation>
    </message>
    <message>
        <source>upload &quot;%1&quot;</source>
        <translation>„%1“ hochladen</translation>
    </message>
    <message>
        <source>route</source>
        <translation>Route</translation>
    </message>
    <message>
        <source>Upload to %1 failed: the vehicle is gone (its connection was closed).</source>
        <translation>Hochladen auf %1 fehlgeschlagen: Das Fahrzeug ist nicht mehr da (seine Verbindung wurde geschlossen).</translation>
    </message>
    <message>
        <source>the vehicle is gone</source>
        <translation>das Fahrzeug ist nicht mehr da</translation>
    </message>
    <message>
        <source>Not uploaded: %1</source>
        <translation>Nicht hochgeladen: %1</translation>
    </message>
    <message>
        <source>Too late to cancel: the mission is being sent to %1.</source>
        <translation>Zu spät zum Abbrechen: Die Mission wird gerade an %1 gesendet.</translation>
    </message>
    <message>
        <source>Upload to %1 cancelled; nothing was sent.</source>
        <translation>Hochladen auf %1 abgebrochen; es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>Upload to %1 failed: the vehicle has no link.</source>
        <translation>Hochladen auf %1 fehlgeschlagen: Das Fahrzeug hat keine Verbindung.</translation>
    </message>
    <message>
        <source>no link</source>
        <translation>keine Verbindung</translation>
    </message>
    <message>
        <source>Not uploaded to %1: %2</source>
        <translation>Nicht auf %1 hochgeladen: %2</translation>
    </message>
    <message>
        <source>the route&apos;s fence is not sent: %1 keeps no fence (HCI)</source>
        <translation>der Geofence der Route wird nicht gesendet: %1 speichert keinen Geofence (HCI)</translation>
    </message>
    <message>
        <source>Upload to %1 failed: %2</source>
        <translation>Hochladen auf %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>Uploaded to %1, but it could not be read back: %2</source>
        <translation>Auf %1 hochgeladen, aber das Zurücklesen schlug fehl: %2</translation>
    </message>
    <message>
        <source>Uploaded to %1, but it holds something else: %2</source>
        <translation>Auf %1 hochgeladen, aber es enthält etwas anderes: %2</translation>
    </message>
    <message numerus="yes">
        <source>Uploaded to %1: %n waypoint(s).</source>
        <translation>
            <numerusform>Auf %1 hochgeladen: %n Wegpunkt.</numerusform>
            <numerusform>Auf %1 hochgeladen: %n Wegpunkte.</numerusform>
        </translation>
    </message>
    <message>
        <source>Note: %1</source>
        <translation>Hinweis: %1</translation>
    </message>
</context>
<context>
    <name>sortie::client::RouteAutosave</name>
    <message>
        <source>No free autosave slot in %1: edits are not autosaved.</source>
        <translation>Kein freier Platz für automatische Sicherungen in %1: Änderungen werden nicht automatisch gesichert.</translation>
    </message>
</context>
<context>
    <name>sortie::client::RouteDocument</name>
    <message>
        <source>Import failed: %1</source>
        <translation>Import fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Import failed: %1 holds no route.</source>
        <translation>Import fehlgeschlagen: %1 enthält keine Route.</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Import von %1</translation>
    </message>
    <message numerus="yes">
        <source>Imported %n segment(s) from %1.</source>
        <translation>
            <numerusform>%n Segment aus %1 importiert.</numerusform>
            <numerusform>%n Segmente aus %1 importiert.</numerusform>
        </translation>
    </message>
    <message>
        <source>The file holds %1 routes; this is the first (&quot;%2&quot;).</source>
        <translation>Die Datei enthält %1 Routen; dies ist die erste („%2“).</translation>
    </message>
    <message>
        <source>Export failed: %1</source>
        <translation>Export fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation>Exportiert nach %1.</translation>
    </message>
    <message>
        <source>Not representable there: %1</source>
        <translation>Dort nicht darstellbar: %1</translation>
    </message>
</context>
<context>
    <name>sortie::client::RoutePreparation</name>
    <message>
        <source>Choose the vehicle to %1 for.</source>
        <translation>Wählen Sie das Fahrzeug, für das %1 werden soll.</translation>
    </message>
    <message>
        <source>process the route</source>
        <translation>die Route verarbeitet</translation>
    </message>
    <message>
        <source>%1 has no link.</source>
        <translation>%1 hat keine Verbindung.</translation>
    </message>
    <message>
        <source>Processing for %1…</source>
        <translation>Verarbeitung für %1…</translation>
    </message>
    <message>
        <source>Not processed for %1: %2</source>
        <translation>Nicht für %1 verarbeitet: %2</translation>
    </message>
    <message numerus="yes">
        <source>Processed for %1: %n waypoint(s) to fly.</source>
        <translation>
            <numerusform>Für %1 verarbeitet: %n Wegpunkt zu fliegen.</numerusform>
            <numerusform>Für %1 verarbeitet: %n Wegpunkte zu fliegen.</numerusform>
        </translation>
    </message>
    <message>
        <source>upload</source>
        <translation>hochgeladen</translation>
    </message>
    <message>
        <source>An upload is waiting for your answer.</source>
        <translation>Ein Upload wartet auf Ihre Antwort.</translation>
    </message>
    <message>
        <source>Wait until %1 is done.</source>
        <translation>Bitte warten, bis der laufende Vorgang abgeschlossen ist: %1.</translation>
    </message>
</context>
<context>
    <name>sortie::client::VehicleFleet</name>
    <message>
        <source>%1: %2 done.</source>
        <translation>%1: %2 erledigt.</translation>
    </message>
    <message>
        <source>%1: %2 failed: %3</source>
        <translation>%1: %2 fehlgeschlagen: %3</translation>
    </message>
    <message>
        <source>The server&apos;s vehicles could not be read: %1</source>
        <translation>Die Fahrzeuge des Servers konnten nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>Not a VCI address: %1</source>
        <translation>Keine VCI-Adresse: %1</translation>
    </message>
    <message>
        <source>go to %1, %2 at %3 m</source>
        <translation>Flug zu %1, %2 auf %3 m</translation>
    </message>
    <message>
        <source>%1: flying to the clicked point.</source>
        <translation>%1: fliegt zum angeklickten Punkt.</translation>
    </message>
    <message>
        <source>%1: go-to failed: %2</source>
        <translation>%1: Flug zum Punkt fehlgeschlagen: %2</translation>
    </message>
</context>
<context>
    <name>sortie::client::VehicleGroup</name>
    <message>
        <source>%1 (%2 m)</source>
        <translation>%1 (%2 m)</translation>
    </message>
    <message numerus="yes">
        <source>%1 (%n waypoint(s))</source>
        <translation>
            <numerusform>%1 (%n Wegpunkt)</numerusform>
            <numerusform>%1 (%n Wegpunkte)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Arm %n vehicle(s): %1? Their motors may start.</source>
        <translation>
            <numerusform>%n Fahrzeug scharf schalten: %1? Die Motoren können anlaufen.</numerusform>
            <numerusform>%n Fahrzeuge scharf schalten: %1? Die Motoren können anlaufen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Disarm %n vehicle(s): %1? One in the air would fall.</source>
        <translation>
            <numerusform>%n Fahrzeug entschärfen: %1? Ist es in der Luft, stürzt es ab.</numerusform>
            <numerusform>%n Fahrzeuge entschärfen: %1? Eines in der Luft würde abstürzen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Take off with %n vehicle(s) to their altitudes above home: %1?</source>
        <translation>
            <numerusform>Mit %n Fahrzeug auf seine Höhe über dem Home-Punkt starten: %1?</numerusform>
            <numerusform>Mit %n Fahrzeugen auf ihre Höhen über dem Home-Punkt starten: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Start or resume the mission on %n vehicle(s): %1?</source>
        <translation>
            <numerusform>Mission auf %n Fahrzeug starten oder fortsetzen: %1?</numerusform>
            <numerusform>Mission auf %n Fahrzeugen starten oder fortsetzen: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Pause %n vehicle(s) where they are: %1?</source>
        <translation>
            <numerusform>%n Fahrzeug an Ort und Stelle pausieren: %1?</numerusform>
            <numerusform>%n Fahrzeuge an Ort und Stelle pausieren: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Land %n vehicle(s) where they are: %1?</source>
        <translation>
            <numerusform>%n Fahrzeug an Ort und Stelle landen: %1?</numerusform>
            <numerusform>%n Fahrzeuge an Ort und Stelle landen: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Send %n vehicle(s) home: %1?</source>
        <translation>
            <numerusform>%n Fahrzeug zum Home-Punkt schicken: %1?</numerusform>
            <numerusform>%n Fahrzeuge zum Home-Punkt schicken: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Switch %n vehicle(s) to %2: %1?</source>
        <translation>
            <numerusform>%n Fahrzeug in den Modus %2 schalten: %1?</numerusform>
            <numerusform>%n Fahrzeuge in den Modus %2 schalten: %1?</numerusform>
        </translation>
    </message>
    <message>
        <source>not sent</source>
        <translation>nicht gesendet</translation>
    </message>
    <message>
        <source>%1 waiting</source>
        <translation>%1 wartet</translation>
    </message>
    <message>
        <source>%1 done</source>
        <translation>%1 erledigt</translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation>%1 fehlgeschlagen: %2</translation>
    </message>
    <message numerus="yes">
        <source>%1: %2 of %n vehicle(s) answered — %3.</source>
        <translation>
            <numerusform>%1: %2 von %n Fahrzeug hat geantwortet — %3.</numerusform>
            <numerusform>%1: %2 von %n Fahrzeugen haben geantwortet — %3.</numerusform>
        </translation>
    </message>
    <message>
        <source>Held back by their checklist, not sent: %1.</source>
        <translation>Von ihrer Checkliste zurückgehalten, nicht gesendet: %1.</translation>
    </message>
    <message>
        <source>held back by its checklist (%1)</source>
        <translation>von seiner Checkliste zurückgehalten (%1)</translation>
    </message>
</context>
<context>
    <name>sortie::coverage::PhotoSurvey</name>
    <message>
        <source>Choose the vehicle that took the photos.</source>
        <translation>Wählen Sie das Fahrzeug, das die Fotos aufgenommen hat.</translation>
    </message>
    <message>
        <source>choose the camera that took them</source>
        <translation>wählen Sie die Kamera, die sie aufgenommen hat</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>nicht gemessen</translation>
    </message>
    <message>
        <source>Open the flight&apos;s log first.</source>
        <translation>Öffnen Sie zuerst das Log des Flugs.</translation>
    </message>
    <message>
        <source>Choose the folder of the flight&apos;s photos.</source>
        <translation>Wählen Sie den Ordner mit den Fotos des Flugs.</translation>
    </message>
    <message>
        <source>No photo is placed: nothing to write.</source>
        <translation>Kein Foto ist verortet: nichts zu schreiben.</translation>
    </message>
    <message>
        <source>%1 is the photos&apos; own folder: the copies go elsewhere, the originals are never changed.</source>
        <translation>%1 ist der Ordner der Fotos selbst: die Kopien kommen woandershin, die Originale werden nie verändert.</translation>
    </message>
    <message>
        <source>%1: the folder cannot be made.</source>
        <translation>%1: der Ordner kann nicht angelegt werden.</translation>
    </message>
    <message numerus="yes">
        <source>%n geotagged copies, geo.txt and geotags.csv written to %1.</source>
        <translation>
            <numerusform>%n georeferenzierte Kopie, geo.txt und geotags.csv nach %1 geschrieben.</numerusform>
            <numerusform>%n georeferenzierte Kopien, geo.txt und geotags.csv nach %1 geschrieben.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 not written: %2.</source>
        <translation>%1 nicht geschrieben: %2.</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n photos placed on %2&apos;s track (camera clock %3 s).</source>
        <translation>
            <numerusform>%1 von %n Foto auf der Spur von %2 verortet (Kamerauhr %3 s).</numerusform>
            <numerusform>%1 von %n Fotos auf der Spur von %2 verortet (Kamerauhr %3 s).</numerusform>
        </translation>
    </message>
    <message>
        <source>Coverage not judged: %1.</source>
        <translation>Abdeckung nicht beurteilt: %1.</translation>
    </message>
    <message numerus="yes">
        <source>%1 % of %2 m² seen by at least %3 images; forward overlap %4, side %5; %6 per pixel; %n hole(s).</source>
        <translation>
            <numerusform>%1 % von %2 m² von mindestens %3 Bildern gesehen; Längsüberlappung %4, Querüberlappung %5; %6 pro Pixel; %n Lücke.</numerusform>
            <numerusform>%1 % von %2 m² von mindestens %3 Bildern gesehen; Längsüberlappung %4, Querüberlappung %5; %6 pro Pixel; %n Lücken.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 m² at %2, %3</source>
        <translation>%1 m² bei %2, %3</translation>
    </message>
    <message>
        <source>No hole could be planned as an area scan: %1</source>
        <translation>Keine Lücke ließ sich als Flächenscan planen: %1</translation>
    </message>
    <message>
        <source>Re-fly the gaps</source>
        <translation>Lücken nachfliegen</translation>
    </message>
    <message numerus="yes">
        <source>&quot;Re-fly the gaps&quot; is open in the mission editor: %n area scan(s) at %1 m, %2/%3 % overlap.</source>
        <translation>
            <numerusform>„Lücken nachfliegen“ ist im Missionseditor geöffnet: %n Flächenscan auf %1 m, %2/%3 % Überlappung.</numerusform>
            <numerusform>„Lücken nachfliegen“ ist im Missionseditor geöffnet: %n Flächenscans auf %1 m, %2/%3 % Überlappung.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n photos placed where %2 took them, paired with its photo events (camera clock %3 s off).</source>
        <translation>
            <numerusform>%1 von %n Foto dort platziert, wo %2 es aufnahm, gepaart mit seinen Fotoereignissen (Kamerauhr %3 s daneben).</numerusform>
            <numerusform>%1 von %n Fotos dort platziert, wo %2 sie aufnahm, gepaart mit seinen Fotoereignissen (Kamerauhr %3 s daneben).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n photo(s) the vehicle took are not in the folder.</source>
        <translation>
            <numerusform>%n Foto, das das Fahrzeug aufnahm, fehlt im Ordner.</numerusform>
            <numerusform>%n Fotos, die das Fahrzeug aufnahm, fehlen im Ordner.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::deconfliction::FleetConflictRule</name>
    <message>
        <source>%1, flying &quot;%2&quot; (its leg %3)</source>
        <translation>%1 (fliegt „%2“, dort Teilstrecke %3)</translation>
    </message>
    <message>
        <source>%1&apos;s uploaded &quot;%2&quot; (its leg %3) if it starts now</source>
        <translation>der hochgeladenen Route „%2“ von %1 (dort Teilstrecke %3), falls es jetzt startet</translation>
    </message>
    <message>
        <source>Leg %1 comes within %2 m across and %3 m in height of %4, %5 after the start%6.</source>
        <translation>Teilstrecke %1 nähert sich %4 auf %2 m seitlich und %3 m in der Höhe, %5 nach dem Start%6.</translation>
    </message>
    <message>
        <source> (heights in different frames: judged across only)</source>
        <translation> (Höhen in verschiedenen Bezugssystemen: nur seitlich beurteilt)</translation>
    </message>
</context>
<context>
    <name>sortie::deconfliction::ProximityMonitor</name>
    <message>
        <source>now</source>
        <translation>jetzt</translation>
    </message>
    <message>
        <source>in %1 s</source>
        <translation>in %1 s</translation>
    </message>
    <message>
        <source>%1 and traffic %2: closest %3, %4 across and %5 in height</source>
        <translation>%1 und Verkehr %2: geringster Abstand %3, %4 seitlich und %5 in der Höhe</translation>
    </message>
    <message>
        <source>%1 and %2: closest %3, %4 across and %5 in height</source>
        <translation>%1 und %2: geringster Abstand %3, %4 seitlich und %5 in der Höhe</translation>
    </message>
</context>
<context>
    <name>sortie::endurance::EnduranceAdvisory</name>
    <message>
        <source>No vehicle chosen</source>
        <translation>Kein Fahrzeug gewählt</translation>
    </message>
    <message>
        <source>No energy profile: choose the vehicle&apos;s profile file on the mission page</source>
        <translation>Kein Energieprofil: Wählen Sie die Profildatei des Fahrzeugs auf der Missionsseite</translation>
    </message>
    <message>
        <source>The vehicle reports no remaining battery</source>
        <translation>Das Fahrzeug meldet keine Akku-Restkapazität</translation>
    </message>
    <message>
        <source>The vehicle reports no home</source>
        <translation>Das Fahrzeug meldet keinen Home-Punkt</translation>
    </message>
    <message>
        <source>The vehicle reports no position</source>
        <translation>Das Fahrzeug meldet keine Position</translation>
    </message>
    <message>
        <source>No mission on board</source>
        <translation>Keine Mission an Bord</translation>
    </message>
    <message>
        <source>The vehicle cannot make headway home against the wind</source>
        <translation>Das Fahrzeug kommt gegen den Wind nicht zum Home-Punkt voran</translation>
    </message>
    <message>
        <source>Battery at end of route: %1 · home needs %2</source>
        <translation>Akku am Routenende: %1 · Rückflug braucht %2</translation>
    </message>
    <message>
        <source>Battery: time to come home — no headway home against the wind</source>
        <translation>Akku: Zeit für die Rückkehr — gegen den Wind kein Vorankommen zum Home-Punkt</translation>
    </message>
    <message>
        <source>Battery: time to come home — %1 left, home needs %2: the %3 reserve is being used</source>
        <translation>Akku: Zeit für die Rückkehr — %1 übrig, Rückflug braucht %2: Die Reserve von %3 wird angegriffen</translation>
    </message>
    <message>
        <source>Battery: time to come home — %1 left, home needs %2 and the reserve %3: %4 to spare</source>
        <translation>Akku: Zeit für die Rückkehr — %1 übrig, Rückflug braucht %2 und die Reserve %3: %4 Spielraum</translation>
    </message>
    <message>
        <source>Return %1 home now? %2</source>
        <translation>%1 jetzt zum Home-Punkt zurückholen? %2</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ComparisonController</name>
    <message>
        <source>Open a flight log first.</source>
        <translation>Öffnen Sie zuerst ein Flugprotokoll.</translation>
    </message>
    <message>
        <source>%1 holds no route.</source>
        <translation>%1 enthält keine Route.</translation>
    </message>
    <message>
        <source>Choose the vehicle to compare on the map or in the list.</source>
        <translation>Wählen Sie das zu vergleichende Fahrzeug auf der Karte oder in der Liste.</translation>
    </message>
    <message>
        <source>%1 on &quot;%2&quot;: %3 of %4 waypoints reached; cross-track max %5 m, mean %6 m; altitude max %7 m</source>
        <translation>%1 auf „%2“: %3 von %4 Wegpunkten erreicht; Querablage max %5 m, Mittel %6 m; Höhe max %7 m</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::FlightLogWriter</name>
    <message>
        <source>%1: the log cannot use a write-ahead journal</source>
        <translation>%1: Das Protokoll kann kein Write-Ahead-Journal verwenden</translation>
    </message>
    <message>
        <source>Recording could not continue in %1: %2</source>
        <translation>Aufzeichnung konnte in %1 nicht fortgesetzt werden: %2</translation>
    </message>
    <message>
        <source>%1 is being written by another process</source>
        <translation>%1 wird von einem anderen Prozess geschrieben</translation>
    </message>
    <message>
        <source>Recording to %1 failed: %2. What is recorded meanwhile is kept and written once it can be.</source>
        <translation>Aufzeichnung in %1 fehlgeschlagen: %2. Was inzwischen aufgezeichnet wird, bleibt erhalten und wird geschrieben, sobald es geht.</translation>
    </message>
    <message numerus="yes">
        <source>Recording to %1 resumed; %n value(s) recorded while it failed could not be kept.</source>
        <translation>
            <numerusform>Aufzeichnung in %1 fortgesetzt; %n während des Fehlers aufgezeichneter Wert konnte nicht behalten werden.</numerusform>
            <numerusform>Aufzeichnung in %1 fortgesetzt; %n während des Fehlers aufgezeichnete Werte konnten nicht behalten werden.</numerusform>
        </translation>
    </message>
    <message>
        <source>no row for vehicle %1: %2</source>
        <translation>keine Zeile für Fahrzeug %1: %2</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::FlightRecorder</name>
    <message>
        <source>The flight log %1 cannot be written: %2</source>
        <translation>Das Flugprotokoll %1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>Recording started</source>
        <translation>Aufzeichnung gestartet</translation>
    </message>
    <message>
        <source>Recording stopped</source>
        <translation>Aufzeichnung beendet</translation>
    </message>
    <message>
        <source>Route of 1 waypoint</source>
        <translation>Route mit 1 Wegpunkt</translation>
    </message>
    <message>
        <source>Route of %1 waypoints</source>
        <translation>Route mit %1 Wegpunkten</translation>
    </message>
    <message>
        <source>Armed</source>
        <translation>Scharf geschaltet</translation>
    </message>
    <message>
        <source>Disarmed</source>
        <translation>Entschärft</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::RecordingSettings</name>
    <message>
        <source>In force: %1; %2.</source>
        <translation>Gültig: %1; %2.</translation>
    </message>
    <message>
        <source>a log up to %1 MB</source>
        <translation>ein Protokoll bis %1 MB</translation>
    </message>
    <message>
        <source>logs of any size</source>
        <translation>Protokolle beliebiger Größe</translation>
    </message>
    <message>
        <source>the folder up to %1 MB</source>
        <translation>der Ordner bis %1 MB</translation>
    </message>
    <message>
        <source>the folder without limit</source>
        <translation>der Ordner ohne Grenze</translation>
    </message>
    <message>
        <source>A log&apos;s size must be between 1 and %1 MB, or 0 for no limit.</source>
        <translation>Die Größe eines Protokolls muss zwischen 1 und %1 MB liegen, oder 0 für keine Grenze.</translation>
    </message>
    <message>
        <source>The folder&apos;s size must be between 1 and %1 MB, or 0 for no limit.</source>
        <translation>Die Größe des Ordners muss zwischen 1 und %1 MB liegen, oder 0 für keine Grenze.</translation>
    </message>
    <message>
        <source>The folder must hold at least one whole log: make its limit at least a log&apos;s size (%1 MB).</source>
        <translation>Der Ordner muss mindestens ein ganzes Protokoll fassen: Setzen Sie seine Grenze mindestens auf die Protokollgröße (%1 MB).</translation>
    </message>
    <message>
        <source>%1 in 1 log</source>
        <translation>%1 in 1 Protokoll</translation>
    </message>
    <message>
        <source>%1 in %2 logs</source>
        <translation>%1 in %2 Protokollen</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ReplayController</name>
    <message>
        <source>%1 of 1 vehicle</source>
        <translation>%1 von 1 Fahrzeug</translation>
    </message>
    <message>
        <source>%1 of %2 vehicles</source>
        <translation>%1 von %2 Fahrzeugen</translation>
    </message>
    <message>
        <source>No log is open.</source>
        <translation>Kein Protokoll geöffnet.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an export format (gpx, kml or csv).</source>
        <translation>„%1“ ist kein Exportformat (gpx, kml oder csv).</translation>
    </message>
    <message>
        <source>%1 could not be written: %2</source>
        <translation>%1 konnte nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ServerHistory</name>
    <message>
        <source>not connected to a server</source>
        <translation>nicht mit einem Server verbunden</translation>
    </message>
    <message>
        <source>The server&apos;s history could not be read: %1</source>
        <translation>Der Verlauf des Servers konnte nicht gelesen werden: %1</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ServerHistoryRequest</name>
    <message>
        <source>The server lists no vehicles: connect to a server first.</source>
        <translation>Der Server listet keine Fahrzeuge: Verbinden Sie sich zuerst mit einem Server.</translation>
    </message>
    <message>
        <source>Choose a vehicle.</source>
        <translation>Wählen Sie ein Fahrzeug.</translation>
    </message>
    <message>
        <source>The start &quot;%1&quot; is not a time like %2 (UTC).</source>
        <translation>Der Beginn „%1“ ist keine Zeit wie %2 (UTC).</translation>
    </message>
    <message>
        <source>The end &quot;%1&quot; is not a time like %2 (UTC).</source>
        <translation>Das Ende „%1“ ist keine Zeit wie %2 (UTC).</translation>
    </message>
    <message>
        <source>The start must be before the end.</source>
        <translation>Der Beginn muss vor dem Ende liegen.</translation>
    </message>
    <message>
        <source>The start is in the future.</source>
        <translation>Der Beginn liegt in der Zukunft.</translation>
    </message>
    <message>
        <source>At most 24 hours at a time.</source>
        <translation>Höchstens 24 Stunden auf einmal.</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>The server has no telemetry of %1 from %2 to %3 UTC.</source>
        <translation>Der Server hat keine Telemetrie von %1 zwischen %2 und %3 UTC.</translation>
    </message>
    <message>
        <source>There is no replay to show it in.</source>
        <translation>Es gibt keine Wiedergabe, in der sie gezeigt werden kann.</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ServerRecording</name>
    <message>
        <source>logged in to %1 as %2; recording to %3</source>
        <translation>angemeldet bei %1 als %2; Aufzeichnung in %3</translation>
    </message>
    <message>
        <source>server: %1</source>
        <translation>Server: %1</translation>
    </message>
    <message>
        <source>1 vehicle</source>
        <translation>1 Fahrzeug</translation>
    </message>
    <message>
        <source>%1 vehicles</source>
        <translation>%1 Fahrzeuge</translation>
    </message>
    <message>
        <source>log closed: %1</source>
        <translation>Protokoll geschlossen: %1</translation>
    </message>
    <message>
        <source>a pinned certificate needs a tls://host:port server and a SHA-256 fingerprint</source>
        <translation>ein festgelegtes Zertifikat braucht einen Server tls://host:port und einen SHA-256-Fingerabdruck</translation>
    </message>
    <message>
        <source>%1 is not this computer and the connection is not secured: the password would cross the network in clear. Record over TLS (--server tls://%1), or pass --allow-cleartext to send it in clear.</source>
        <translation>%1 ist nicht dieser Computer und die Verbindung ist nicht gesichert: Das Passwort ginge im Klartext über das Netz. Zeichnen Sie über TLS auf (--server tls://%1) oder geben Sie --allow-cleartext an, um es im Klartext zu senden.</translation>
    </message>
</context>
<context>
    <name>sortie::gamepad::GamepadCommands</name>
    <message>
        <source>Gamepads off</source>
        <translation>Gamepads aus</translation>
    </message>
    <message>
        <source>Gamepads unavailable: %1</source>
        <translation>Gamepads nicht verfügbar: %1</translation>
    </message>
    <message>
        <source>No gamepad attached</source>
        <translation>Kein Gamepad angeschlossen</translation>
    </message>
</context>
<context>
    <name>sortie::gamepad::GamepadManager</name>
    <message>
        <source>Another gamepad manager already owns SDL in this program.</source>
        <translation>Eine andere Gamepad-Verwaltung besitzt SDL in diesem Programm bereits.</translation>
    </message>
    <message>
        <source>Gamepads are not available: %1</source>
        <translation>Gamepads sind nicht verfügbar: %1</translation>
    </message>
</context>
<context>
    <name>sortie::maptiles::OfflineMaps</name>
    <message>
        <source>No route is open.</source>
        <translation>Keine Route geöffnet.</translation>
    </message>
    <message>
        <source>The open route has no waypoints to take the area from.</source>
        <translation>Die geöffnete Route hat keine Wegpunkte, aus denen sich das Gebiet ergibt.</translation>
    </message>
    <message>
        <source>The route is a single point: give a margin around it.</source>
        <translation>Die Route ist ein einzelner Punkt: Geben Sie einen Rand darum an.</translation>
    </message>
    <message numerus="yes">
        <source>The open route (%n point(s)) and %1 m around it</source>
        <translation>
            <numerusform>Die geöffnete Route (%n Punkt) und %1 m darum herum</numerusform>
            <numerusform>Die geöffnete Route (%n Punkte) und %1 m darum herum</numerusform>
        </translation>
    </message>
    <message>
        <source>The map&apos;s view is not an area (%1 to %2).</source>
        <translation>Der Kartenausschnitt ist kein Gebiet (%1 bis %2).</translation>
    </message>
    <message>
        <source>The map&apos;s view</source>
        <translation>Der Kartenausschnitt</translation>
    </message>
    <message>
        <source>The lowest zoom is above the highest.</source>
        <translation>Die niedrigste Zoomstufe liegt über der höchsten.</translation>
    </message>
    <message>
        <source>Choose an area.</source>
        <translation>Wählen Sie ein Gebiet.</translation>
    </message>
    <message>
        <source>%1 tiles, about %2</source>
        <translation>%1 Kacheln, etwa %2</translation>
    </message>
    <message>
        <source> (at this pack&apos;s mean of %1 a tile)</source>
        <translation> (beim Mittelwert dieses Pakets von %1 pro Kachel)</translation>
    </message>
    <message>
        <source> (assuming %1 a tile)</source>
        <translation> (angenommen %1 pro Kachel)</translation>
    </message>
    <message>
        <source>: more than the limit of %1 tiles, choose a smaller area or fewer zoom levels</source>
        <translation>: mehr als die Grenze von %1 Kacheln; wählen Sie ein kleineres Gebiet oder weniger Zoomstufen</translation>
    </message>
    <message>
        <source>Choose a web tile server in Map source first: %1</source>
        <translation>Wählen Sie zuerst unter Kartenquelle einen Web-Kachelserver: %1</translation>
    </message>
    <message>
        <source>%1 of %2 tiles</source>
        <translation>%1 von %2 Kacheln</translation>
    </message>
    <message>
        <source> · %1 already in the pack</source>
        <translation> · %1 schon im Paket</translation>
    </message>
    <message>
        <source> · %1 not stored</source>
        <translation> · %1 nicht gespeichert</translation>
    </message>
    <message>
        <source> · paused</source>
        <translation> · pausiert</translation>
    </message>
    <message>
        <source> · done</source>
        <translation> · fertig</translation>
    </message>
    <message>
        <source> · stopped</source>
        <translation> · gestoppt</translation>
    </message>
    <message>
        <source> · failed</source>
        <translation> · fehlgeschlagen</translation>
    </message>
    <message>
        <source>The drawn area cannot be used: %1</source>
        <translation>Das gezeichnete Gebiet ist nicht verwendbar: %1</translation>
    </message>
    <message numerus="yes">
        <source>A drawn area (%n corner(s))</source>
        <translation>
            <numerusform>Ein gezeichnetes Gebiet (%n Ecke)</numerusform>
            <numerusform>Ein gezeichnetes Gebiet (%n Ecken)</numerusform>
        </translation>
    </message>
    <message>
        <source>The drawn rectangle is not an area (%1 to %2).</source>
        <translation>Das gezeichnete Rechteck ist kein Gebiet (%1 bis %2).</translation>
    </message>
    <message>
        <source>A drawn rectangle</source>
        <translation>Ein gezeichnetes Rechteck</translation>
    </message>
</context>
<context>
    <name>sortie::maptiles::TilePrefetch</name>
    <message>
        <source>No area is chosen.</source>
        <translation>Kein Gebiet gewählt.</translation>
    </message>
    <message>
        <source>The zoom range %1 to %2 is not within 0 to %3.</source>
        <translation>Der Zoombereich %1 bis %2 liegt nicht innerhalb von 0 bis %3.</translation>
    </message>
    <message>
        <source>The area needs %1 tiles, more than the limit of %2: choose a smaller area or fewer zoom levels.</source>
        <translation>Das Gebiet braucht %1 Kacheln, mehr als die Grenze von %2: Wählen Sie ein kleineres Gebiet oder weniger Zoomstufen.</translation>
    </message>
    <message>
        <source>Tiles from %1, taken offline by %2</source>
        <translation>Kacheln von %1, offline gespeichert mit %2</translation>
    </message>
    <message>
        <source>not an image (%1, %2 bytes)</source>
        <translation>kein Bild (%1, %2 Bytes)</translation>
    </message>
    <message>
        <source>no answer within %1 s</source>
        <translation>keine Antwort innerhalb von %1 s</translation>
    </message>
    <message>
        <source>%1 (after %2 attempts)</source>
        <translation>%1 (nach %2 Versuchen)</translation>
    </message>
</context>
<context>
    <name>sortie::mission::RouteEditor</name>
    <message>
        <source>Nothing is selected.</source>
        <translation>Nichts ausgewählt.</translation>
    </message>
    <message>
        <source>That is not a valid position.</source>
        <translation>Das ist keine gültige Position.</translation>
    </message>
    <message>
        <source>There is no row %1 to insert at.</source>
        <translation>Es gibt keine Zeile %1 zum Einfügen.</translation>
    </message>
    <message>
        <source>Add waypoint %1</source>
        <translation>Wegpunkt %1 hinzufügen</translation>
    </message>
    <message>
        <source>A move needs one position per waypoint.</source>
        <translation>Zum Verschieben wird eine Position pro Wegpunkt benötigt.</translation>
    </message>
    <message>
        <source>There is no row %1.</source>
        <translation>Es gibt keine Zeile %1.</translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>%1 verschieben</translation>
    </message>
    <message numerus="yes">
        <source>Move %n segment(s)</source>
        <translation>
            <numerusform>%n Segment verschieben</numerusform>
            <numerusform>%n Segmente verschieben</numerusform>
        </translation>
    </message>
    <message>
        <source>Row %1 is not a waypoint.</source>
        <translation>Zeile %1 ist kein Wegpunkt.</translation>
    </message>
    <message>
        <source>The altitude needs a number.</source>
        <translation>Die Höhe braucht eine Zahl.</translation>
    </message>
    <message>
        <source>Set altitude to %1 m</source>
        <translation>Höhe auf %1 m setzen</translation>
    </message>
    <message>
        <source>Set altitude type to %1</source>
        <translation>Höhenbezug auf %1 setzen</translation>
    </message>
    <message>
        <source>Row %1 keeps its height %2: set it as %2, or change its altitude type first.</source>
        <translation>Zeile %1 behält ihre Höhe %2: Setzen Sie sie als %2 oder ändern Sie zuerst ihren Höhenbezug.</translation>
    </message>
    <message>
        <source>Waypoint %1 is planned %2 and there is no terrain data under it: a height %3 cannot be converted.</source>
        <translation>Wegpunkt %1 ist %2 geplant, und unter ihm gibt es keine Geländedaten: Eine Höhe %3 kann nicht umgerechnet werden.</translation>
    </message>
    <message>
        <source>Set altitude to %1 m %2</source>
        <translation>Höhe auf %1 m %2 setzen</translation>
    </message>
    <message>
        <source>Set turn type to %1</source>
        <translation>Kurvenart auf %1 setzen</translation>
    </message>
    <message>
        <source>No selected segment has a parameter &quot;%1&quot;.</source>
        <translation>Kein ausgewähltes Segment hat einen Parameter „%1“.</translation>
    </message>
    <message>
        <source>Set %1 to %2</source>
        <translation>%1 auf %2 setzen</translation>
    </message>
    <message>
        <source>There is no action &quot;%1&quot;.</source>
        <translation>Es gibt keine Aktion „%1“.</translation>
    </message>
    <message>
        <source>Add action: %1</source>
        <translation>Aktion hinzufügen: %1</translation>
    </message>
    <message>
        <source>Remove action</source>
        <translation>Aktion entfernen</translation>
    </message>
    <message>
        <source>There is no action &quot;%1&quot; with these values.</source>
        <translation>Es gibt keine Aktion „%1“ mit diesen Werten.</translation>
    </message>
    <message>
        <source>Edit action: %1</source>
        <translation>Aktion bearbeiten: %1</translation>
    </message>
    <message>
        <source>Clear actions</source>
        <translation>Aktionen löschen</translation>
    </message>
    <message>
        <source>An area scan needs at least three corners that enclose an area.</source>
        <translation>Ein Flächenscan braucht mindestens drei Ecken, die eine Fläche einschließen.</translation>
    </message>
    <message>
        <source>Add area scan</source>
        <translation>Flächenscan hinzufügen</translation>
    </message>
    <message>
        <source>Segment %1 has no point %2.</source>
        <translation>Segment %1 hat keinen Punkt %2.</translation>
    </message>
    <message>
        <source>Move point %1 of segment %2</source>
        <translation>Punkt %1 von Segment %2 verschieben</translation>
    </message>
    <message>
        <source>Segment %1 has no edge there.</source>
        <translation>Segment %1 hat dort keine Kante.</translation>
    </message>
    <message>
        <source>Add a point to segment %1</source>
        <translation>Punkt zu Segment %1 hinzufügen</translation>
    </message>
    <message numerus="yes">
        <source>This figure keeps at least %n point(s).</source>
        <translation>
            <numerusform>Diese Figur behält mindestens %n Punkt.</numerusform>
            <numerusform>Diese Figur behält mindestens %n Punkte.</numerusform>
        </translation>
    </message>
    <message>
        <source>Remove point %1 of segment %2</source>
        <translation>Punkt %1 von Segment %2 entfernen</translation>
    </message>
    <message>
        <source>A radius is above 0 m.</source>
        <translation>Ein Radius liegt über 0 m.</translation>
    </message>
    <message>
        <source>Segment %1 is no circle.</source>
        <translation>Segment %1 ist kein Kreis.</translation>
    </message>
    <message>
        <source>Set the radius of segment %1 to %2 m</source>
        <translation>Radius von Segment %1 auf %2 m setzen</translation>
    </message>
    <message>
        <source>A point segment needs one valid position.</source>
        <translation>Ein Punktsegment braucht eine gültige Position.</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>%1 hinzufügen</translation>
    </message>
    <message>
        <source>Sortie has no description of the algorithm %1.</source>
        <translation>Sortie hat keine Beschreibung des Algorithmus %1.</translation>
    </message>
    <message numerus="yes">
        <source>%1 needs at least %n point(s)%2.</source>
        <translation>
            <numerusform>%1 braucht mindestens %n Punkt%2.</numerusform>
            <numerusform>%1 braucht mindestens %n Punkte%2.</numerusform>
        </translation>
    </message>
    <message>
        <source> enclosing an area</source>
        <translation>, die eine Fläche einschließen</translation>
    </message>
    <message>
        <source>A route has no setting &quot;%1&quot;.</source>
        <translation>Eine Route hat keine Einstellung „%1“.</translation>
    </message>
    <message>
        <source>%1 needs a number.</source>
        <translation>%1 braucht eine Zahl.</translation>
    </message>
    <message>
        <source>Set route %1</source>
        <translation>Routeneinstellung %1 setzen</translation>
    </message>
    <message>
        <source>Plan the start for %1</source>
        <translation>Start für %1 planen</translation>
    </message>
    <message>
        <source>Start now</source>
        <translation>Jetzt starten</translation>
    </message>
    <message>
        <source>An authorisation needs the zone&apos;s identifier.</source>
        <translation>Eine Genehmigung braucht die Kennung der Zone.</translation>
    </message>
    <message>
        <source>Remove the authorisation for %1</source>
        <translation>Die Genehmigung für %1 entfernen</translation>
    </message>
    <message>
        <source>Record authorisation %1 for %2</source>
        <translation>Genehmigung %1 für %2 eintragen</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no start time: type it as %2, e.g. %3.</source>
        <translation>„%1“ ist keine Startzeit: geben Sie sie als %2 ein, z. B. %3.</translation>
    </message>
</context>
<context>
    <name>sortie::mission::SegmentEditorModel</name>
    <message>
        <source>A parameter Sortie has no description of: kept and sent as typed.</source>
        <translation>Ein Parameter, den Sortie nicht beschreibt: wird so behalten und gesendet, wie eingegeben.</translation>
    </message>
    <message>
        <source>%1 (vehicle profile)</source>
        <translation>%1 (Fahrzeugprofil)</translation>
    </message>
    <message>
        <source>%1 needs a number, not &quot;%2&quot;.</source>
        <translation>%1 braucht eine Zahl, nicht „%2“.</translation>
    </message>
    <message>
        <source>%1 m high · %2 cm/px · footprint %3 × %4 m · passes %5 m apart · photo every %6 m · %7 photos</source>
        <translation>%1 m hoch · %2 cm/px · Bildfläche %3 × %4 m · Bahnen %5 m auseinander · Foto alle %6 m · %7 Fotos</translation>
    </message>
</context>
<context>
    <name>sortie::mission::SegmentPreview</name>
    <message>
        <source>This segment cannot be planned.</source>
        <translation>Dieses Segment kann nicht geplant werden.</translation>
    </message>
</context>
<context>
    <name>sortie::mission::WaypointActionsModel</name>
    <message>
        <source>Actions at waypoint %1</source>
        <translation>Aktionen an Wegpunkt %1</translation>
    </message>
    <message>
        <source>Actions at %1 waypoints</source>
        <translation>Aktionen an %1 Wegpunkten</translation>
    </message>
    <message>
        <source>There is no action &quot;%1&quot;.</source>
        <translation>Es gibt keine Aktion „%1“.</translation>
    </message>
    <message>
        <source>This action has no field &quot;%1&quot;.</source>
        <translation>Diese Aktion hat kein Feld „%1“.</translation>
    </message>
    <message>
        <source>Choose an action to add.</source>
        <translation>Wählen Sie eine Aktion zum Hinzufügen.</translation>
    </message>
</context>
<context>
    <name>sortie::preflight::PreflightChecklists</name>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
</context>
<context>
    <name>sortie::preflight::VehicleChecklist</name>
    <message>
        <source>2D fix</source>
        <translation>2D-Fix</translation>
    </message>
    <message>
        <source>3D fix</source>
        <translation>3D-Fix</translation>
    </message>
    <message>
        <source>RTK float</source>
        <translation>RTK Float</translation>
    </message>
    <message>
        <source>RTK fixed</source>
        <translation>RTK Fixed</translation>
    </message>
    <message>
        <source>no fix</source>
        <translation>kein Fix</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Link to the vehicle</source>
        <translation>Verbindung zum Fahrzeug</translation>
    </message>
    <message>
        <source>GPS fix</source>
        <translation>GPS-Fix</translation>
    </message>
    <message>
        <source>Satellites</source>
        <translation>Satelliten</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Akku</translation>
    </message>
    <message>
        <source>Home position</source>
        <translation>Heimatposition</translation>
    </message>
    <message>
        <source>Route on board</source>
        <translation>Route an Bord</translation>
    </message>
    <message>
        <source>Route check</source>
        <translation>Routenprüfung</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>ticked</source>
        <translation>abgehakt</translation>
    </message>
    <message>
        <source>not reported over this vehicle&apos;s link</source>
        <translation>über die Verbindung dieses Fahrzeugs nicht gemeldet</translation>
    </message>
    <message>
        <source>to tick</source>
        <translation>abzuhaken</translation>
    </message>
    <message>
        <source>Sortie has uploaded no route to it</source>
        <translation>Sortie hat ihm keine Route hochgeladen</translation>
    </message>
    <message>
        <source>its route is not the one open</source>
        <translation>seine Route ist nicht die geöffnete</translation>
    </message>
    <message>
        <source>not known: no fresh telemetry</source>
        <translation>unbekannt: keine aktuelle Telemetrie</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>verbunden</translation>
    </message>
    <message>
        <source>no fresh telemetry</source>
        <translation>keine aktuelle Telemetrie</translation>
    </message>
    <message>
        <source>%1 (%2 needed)</source>
        <translation>%1 (%2 nötig)</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>%1 % (%2 % needed)</source>
        <translation>%1 % (%2 % nötig)</translation>
    </message>
    <message>
        <source>set</source>
        <translation>gesetzt</translation>
    </message>
    <message>
        <source>not set</source>
        <translation>nicht gesetzt</translation>
    </message>
    <message>
        <source>the planned route</source>
        <translation>die geplante Route</translation>
    </message>
    <message>
        <source>differs from the planned route: upload it</source>
        <translation>weicht von der geplanten Route ab: hochladen</translation>
    </message>
    <message>
        <source>no errors</source>
        <translation>keine Fehler</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n Fehler</numerusform>
            <numerusform>%n Fehler</numerusform>
        </translation>
    </message>
    <message>
        <source>stream reported</source>
        <translation>Stream gemeldet</translation>
    </message>
    <message>
        <source>no stream reported</source>
        <translation>kein Stream gemeldet</translation>
    </message>
</context>
<context>
    <name>sortie::resume::MissionResume</name>
    <message>
        <source>The route</source>
        <translation>Die Route</translation>
    </message>
    <message numerus="yes">
        <source>%1 stopped flying to waypoint %2 of %3, after %n photo(s).</source>
        <translation>
            <numerusform>%1 stoppte im Flug zu Wegpunkt %2 von %3, nach %n Foto.</numerusform>
            <numerusform>%1 stoppte im Flug zu Wegpunkt %2 von %3, nach %n Fotos.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 stopped flying to waypoint %2 of %3.</source>
        <translation>%1 stoppte im Flug zu Wegpunkt %2 von %3.</translation>
    </message>
    <message>
        <source>There is nothing to resume: no vehicle stands with a route flown part of the way.</source>
        <translation>Es gibt nichts fortzusetzen: kein Fahrzeug steht mit einer teilweise geflogenen Route bereit.</translation>
    </message>
    <message>
        <source>The vehicle took no photo on this route.</source>
        <translation>Das Fahrzeug hat auf dieser Route kein Foto aufgenommen.</translation>
    </message>
    <message>
        <source>The vehicle reached no waypoint of this route.</source>
        <translation>Das Fahrzeug hat keinen Wegpunkt dieser Route erreicht.</translation>
    </message>
    <message>
        <source>Resume the mission</source>
        <translation>Mission fortsetzen</translation>
    </message>
</context>
<context>
    <name>sortie::secrets::PasswordVault</name>
    <message>
        <source>the keyring did not answer</source>
        <translation>der Schlüsselbund hat nicht geantwortet</translation>
    </message>
</context>
<context>
    <name>sortie::traffic::SbsFeed</name>
    <message>
        <source>no answer within %1 s</source>
        <translation>keine Antwort innerhalb von %1 s</translation>
    </message>
    <message>
        <source>the receiver closed the connection</source>
        <translation>der Empfänger hat die Verbindung geschlossen</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not host:port</source>
        <translation>„%1“ ist nicht Host:Port</translation>
    </message>
    <message>
        <source>receiver off</source>
        <translation>Empfänger aus</translation>
    </message>
    <message>
        <source>receiver: %1</source>
        <translation>Empfänger: %1</translation>
    </message>
    <message>
        <source>receiver: connecting to %1</source>
        <translation>Empfänger: Verbindung zu %1 wird aufgebaut</translation>
    </message>
    <message>
        <source>receiver %1</source>
        <translation>Empfänger %1</translation>
    </message>
    <message>
        <source>receiver: %1; again in %2 s</source>
        <translation>Empfänger: %1; neuer Versuch in %2 s</translation>
    </message>
</context>
<context>
    <name>sortie::ui::AppSettings</name>
    <message>
        <source>The password an earlier version kept in the settings file is now in the keyring.</source>
        <translation>Das Passwort, das eine frühere Version in der Einstellungsdatei abgelegt hatte, liegt jetzt im Schlüsselbund.</translation>
    </message>
    <message>
        <source>The password an earlier version kept in the settings file was erased from it; the keyring refused it (%1), so it is not remembered.</source>
        <translation>Das Passwort, das eine frühere Version in der Einstellungsdatei abgelegt hatte, wurde dort gelöscht; der Schlüsselbund hat es abgelehnt (%1), daher wird es nicht gespeichert.</translation>
    </message>
    <message>
        <source>The keyring refused the password (%1): it is not remembered.</source>
        <translation>Der Schlüsselbund hat das Passwort abgelehnt (%1): Es wird nicht gespeichert.</translation>
    </message>
    <message>
        <source>The remembered password could not be read from the keyring (%1).</source>
        <translation>Das gespeicherte Passwort konnte nicht aus dem Schlüsselbund gelesen werden (%1).</translation>
    </message>
    <message>
        <source>The password could not be removed from the keyring (%1).</source>
        <translation>Das Passwort konnte nicht aus dem Schlüsselbund entfernt werden (%1).</translation>
    </message>
    <message>
        <source>No keyring is reachable, so the password cannot be remembered (%1).</source>
        <translation>Kein Schlüsselbund erreichbar, daher kann das Passwort nicht gespeichert werden (%1).</translation>
    </message>
    <message>
        <source>The password an earlier version kept in the settings file was erased from it.</source>
        <translation>Das Passwort, das eine frühere Version in der Einstellungsdatei abgelegt hatte, wurde dort gelöscht.</translation>
    </message>
</context>
<context>
    <name>sortie::ui::AttitudeIndicator</name>
    <message>
        <source>no attitude</source>
        <translation>keine Fluglage</translation>
    </message>
</context>
<context>
    <name>sortie::ui::ConflictLayer</name>
    <message>
        <source>%1 at %2:%3, %4 m / %5 m</source>
        <translation>%1 um %2:%3, %4 m / %5 m</translation>
    </message>
</context>
<context>
    <name>sortie::ui::DisplayUnits</name>
    <message>
        <source>%1 mi</source>
        <translation>%1 mi</translation>
    </message>
    <message>
        <source>%1 ft</source>
        <translation>%1 ft</translation>
    </message>
    <message>
        <source>%1 km</source>
        <translation>%1 km</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 mph</source>
        <translation>%1 mph</translation>
    </message>
    <message>
        <source>%1 m/s</source>
        <translation>%1 m/s</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>%1 V</source>
        <translation>%1 V</translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>verbindet</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>verbunden</translation>
    </message>
    <message>
        <source>link lost</source>
        <translation>Verbindung verloren</translation>
    </message>
</context>
<context>
    <name>sortie::ui::ElevationProfileView</name>
    <message>
        <source>Leg %1 · %2 · ground %3 · altitude %4 · clearance %5</source>
        <translation>Teilstrecke %1 · %2 · Gelände %3 · Höhe %4 · Bodenabstand %5</translation>
    </message>
    <message>
        <source>no data</source>
        <translation>keine Daten</translation>
    </message>
    <message>
        <source>Add two waypoints to see the terrain profile</source>
        <translation>Fügen Sie zwei Wegpunkte hinzu, um das Geländeprofil zu sehen</translation>
    </message>
    <message>
        <source>No terrain source</source>
        <translation>Keine Geländequelle</translation>
    </message>
    <message>
        <source>Ground: %1</source>
        <translation>Gelände: %1</translation>
    </message>
    <message>
        <source>lowest clearance %1</source>
        <translation>geringster Bodenabstand %1</translation>
    </message>
    <message>
        <source>clearance unknown</source>
        <translation>Bodenabstand unbekannt</translation>
    </message>
    <message>
        <source>no return</source>
        <translation>keine Rückkehr</translation>
    </message>
    <message>
        <source>battery change</source>
        <translation>Akkuwechsel</translation>
    </message>
</context>
<context>
    <name>sortie::ui::EnduranceLayer</name>
    <message>
        <source>Battery change</source>
        <translation>Akkuwechsel</translation>
    </message>
    <message>
        <source>Battery change needed</source>
        <translation>Akkuwechsel nötig</translation>
    </message>
    <message>
        <source>No return</source>
        <translation>Keine Rückkehr</translation>
    </message>
</context>
<context>
    <name>sortie::ui::FlightStatus</name>
    <message>
        <source>mission complete</source>
        <translation>Mission abgeschlossen</translation>
    </message>
    <message>
        <source>waypoint %1 of %2</source>
        <translation>Wegpunkt %1 von %2</translation>
    </message>
    <message>
        <source>1 waypoint on board</source>
        <translation>1 Wegpunkt an Bord</translation>
    </message>
    <message>
        <source>%1 waypoints on board</source>
        <translation>%1 Wegpunkte an Bord</translation>
    </message>
    <message>
        <source>no mission on board</source>
        <translation>keine Mission an Bord</translation>
    </message>
</context>
<context>
    <name>sortie::ui::GlanceStatus</name>
    <message>
        <source>No server</source>
        <translation>Kein Server</translation>
    </message>
    <message>
        <source>No vehicle</source>
        <translation>Kein Fahrzeug</translation>
    </message>
    <message>
        <source>GPS —</source>
        <translation>GPS —</translation>
    </message>
    <message>
        <source>No fix</source>
        <translation>Keine Position</translation>
    </message>
    <message>
        <source>2D fix</source>
        <translation>2D-Position</translation>
    </message>
    <message>
        <source>3D fix</source>
        <translation>3D-Position</translation>
    </message>
    <message>
        <source>RTK float</source>
        <translation>RTK float</translation>
    </message>
    <message>
        <source>RTK fixed</source>
        <translation>RTK fixed</translation>
    </message>
    <message>
        <source>%1, %2 sats</source>
        <translation>%1, %2 Sat.</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>%1 V</source>
        <translation>%1 V</translation>
    </message>
    <message>
        <source>Battery —</source>
        <translation>Akku —</translation>
    </message>
    <message>
        <source>Link lost</source>
        <translation>Verbindung verloren</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>Link —</source>
        <translation>Verbindung —</translation>
    </message>
</context>
<context>
    <name>sortie::ui::MbTilesTileSource</name>
    <message>
        <source>MBTiles</source>
        <translation>MBTiles</translation>
    </message>
    <message>
        <source>No MBTiles file is set.</source>
        <translation>Keine MBTiles-Datei festgelegt.</translation>
    </message>
    <message>
        <source>The MBTiles file has no tile %1.</source>
        <translation>Die MBTiles-Datei hat keine Kachel %1.</translation>
    </message>
    <message>
        <source>Tile %1 in the MBTiles file is not a raster image.</source>
        <translation>Kachel %1 in der MBTiles-Datei ist kein Rasterbild.</translation>
    </message>
</context>
<context>
    <name>sortie::ui::OfflineTileSource</name>
    <message>
        <source>Offline base map</source>
        <translation>Offline-Grundkarte</translation>
    </message>
    <message>
        <source>Land outlines: Natural Earth</source>
        <translation>Landumrisse: Natural Earth</translation>
    </message>
    <message>
        <source>The built-in land outlines could not be read: %1</source>
        <translation>Die eingebauten Landumrisse konnten nicht gelesen werden: %1</translation>
    </message>
</context>
<context>
    <name>sortie::ui::PhotoLayer</name>
    <message>
        <source>Hole %1 m²</source>
        <translation>Lücke %1 m²</translation>
    </message>
</context>
<context>
    <name>sortie::ui::RasterFileCheck</name>
    <message numerus="yes">
        <source>%n file(s) left out, the others are used:</source>
        <translation>
            <numerusform>%n Datei ausgelassen, die anderen werden genutzt:</numerusform>
            <numerusform>%n Dateien ausgelassen, die anderen werden genutzt:</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>and %n more (in the log)</source>
        <translation>
            <numerusform>und %n weitere (im Protokoll)</numerusform>
            <numerusform>und %n weitere (im Protokoll)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::ui::TelemetryPlot</name>
    <message>
        <source>−%1 s</source>
        <translation>−%1 s</translation>
    </message>
    <message>
        <source>now</source>
        <translation>jetzt</translation>
    </message>
    <message>
        <source>No data yet</source>
        <translation>Noch keine Daten</translation>
    </message>
    <message>
        <source>Choose a vehicle</source>
        <translation>Fahrzeug wählen</translation>
    </message>
</context>
<context>
    <name>sortie::ui::TerrainProfileModel</name>
    <message>
        <source>no terrain source</source>
        <translation>keine Geländequelle</translation>
    </message>
    <message>
        <source>no terrain data (tried: %1)</source>
        <translation>keine Geländedaten (versucht: %1)</translation>
    </message>
    <message>
        <source> · loading…</source>
        <translation> · wird geladen…</translation>
    </message>
    <message>
        <source>under this waypoint</source>
        <translation>unter diesem Wegpunkt</translation>
    </message>
    <message>
        <source>under this segment&apos;s points</source>
        <translation>unter den Punkten dieses Segments</translation>
    </message>
    <message>
        <source>Asking for the ground %1…</source>
        <translation>Gelände %1 wird abgefragt…</translation>
    </message>
    <message>
        <source>No terrain data %1 (tried: %2)</source>
        <translation>Keine Geländedaten %1 (versucht: %2)</translation>
    </message>
    <message>
        <source>Ground %1, metres above sea level (EGM96), from %2</source>
        <translation>Gelände %1, Meter über dem Meeresspiegel (EGM96), aus %2</translation>
    </message>
    <message>
        <source>; some points have no data (tried: %1)</source>
        <translation>; einige Punkte haben keine Daten (versucht: %1)</translation>
    </message>
</context>
<context>
    <name>sortie::ui::Theme</name>
    <message>
        <source>System colours</source>
        <translation>Systemfarben</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Hell</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Dunkel</translation>
    </message>
    <message>
        <source>Sunlight (high contrast)</source>
        <translation>Sonnenlicht (hoher Kontrast)</translation>
    </message>
</context>
<context>
    <name>sortie::ui::TileManager</name>
    <message>
        <source>Offline base map</source>
        <translation>Offline-Grundkarte</translation>
    </message>
    <message>
        <source>%1 — offline base map shown</source>
        <translation>%1 — Offline-Grundkarte angezeigt</translation>
    </message>
    <message numerus="yes">
        <source>%1: loading %n tile(s)</source>
        <translation>
            <numerusform>%1: %n Kachel wird geladen</numerusform>
            <numerusform>%1: %n Kacheln werden geladen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %n tile(s) missing — %2</source>
        <translation>
            <numerusform>%1: %n Kachel fehlt — %2</numerusform>
            <numerusform>%1: %n Kacheln fehlen — %2</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::ui::TrafficLayer</name>
    <message>
        <source>%1 ft</source>
        <translation>%1 ft</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source> std</source>
        <translation> STD</translation>
    </message>
    <message>
        <source> climbing</source>
        <translation> steigend</translation>
    </message>
    <message>
        <source> descending</source>
        <translation> sinkend</translation>
    </message>
</context>
<context>
    <name>sortie::ui::Translations</name>
    <message>
        <source>System language</source>
        <translation>Systemsprache</translation>
    </message>
</context>
<context>
    <name>sortie::ui::VideoItem</name>
    <message>
        <source>No video for this vehicle</source>
        <translation>Kein Video für dieses Fahrzeug</translation>
    </message>
    <message>
        <source>hardware decoding (%1)</source>
        <translation>Hardware-Dekodierung (%1)</translation>
    </message>
    <message>
        <source>software decoding (%1)</source>
        <translation>Software-Dekodierung (%1)</translation>
    </message>
</context>
<context>
    <name>sortie::ui::XyzTileSource</name>
    <message>
        <source>Web tiles</source>
        <translation>Web-Kacheln</translation>
    </message>
    <message>
        <source>Tile %1 is not an image.</source>
        <translation>Kachel %1 ist kein Bild.</translation>
    </message>
    <message>
        <source>Tile %1 is neither in the offline pack nor in the cache (cache only: the network is not used).</source>
        <translation>Kachel %1 ist weder im Offline-Paket noch im Cache (nur Cache: Das Netzwerk wird nicht genutzt).</translation>
    </message>
    <message>
        <source>Tile %1 is not in the cache and the tile server is unreachable.</source>
        <translation>Kachel %1 ist nicht im Cache, und der Kachelserver ist nicht erreichbar.</translation>
    </message>
    <message>
        <source>No tile file %1.</source>
        <translation>Keine Kacheldatei %1.</translation>
    </message>
    <message>
        <source>The tile server answered HTTP %1 for tile %2.</source>
        <translation>Der Kachelserver antwortete mit HTTP %1 für Kachel %2.</translation>
    </message>
    <message>
        <source>Tile server unreachable (%1).</source>
        <translation>Kachelserver nicht erreichbar (%1).</translation>
    </message>
    <message>
        <source>Tile %1 is %2.</source>
        <translation>Kachel %1 ist %2.</translation>
    </message>
</context>
<context>
    <name>sortie::ui::ZoneLayer</name>
    <message>
        <source>drawn on the map</source>
        <translation>auf der Karte gezeichnet</translation>
    </message>
    <message>
        <source>%1 (%2 zone)
Source: %3%4
Floor %5, ceiling %6</source>
        <translation>%1 (Zone: %2)
Quelle: %3%4
Untergrenze %5, Obergrenze %6</translation>
    </message>
    <message>
        <source>
Not checked: %1</source>
        <translation>
Nicht geprüft: %1</translation>
    </message>
    <message>
        <source>
Switched off: not checked</source>
        <translation>
Ausgeschaltet: nicht geprüft</translation>
    </message>
    <message>
        <source>
%1 (%2 %3)</source>
        <translation>
%1 (%2 %3)</translation>
    </message>
    <message>
        <source>
Reason: %1</source>
        <translation>
Grund: %1</translation>
    </message>
    <message>
        <source>
When: %1</source>
        <translation>
Wann: %1</translation>
    </message>
    <message>
        <source>
Not in force during the planned flight</source>
        <translation>
Während des geplanten Flugs nicht in Kraft</translation>
    </message>
    <message>
        <source>
Authority: %1</source>
        <translation>
Behörde: %1</translation>
    </message>
</context>
<context>
    <name>sortie::vehicle::CommandLog</name>
    <message>
        <source>sent</source>
        <translation>gesendet</translation>
    </message>
    <message>
        <source>done</source>
        <translation>erledigt</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>alert</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>%1 %2: %3 %4</source>
        <translation>%1 %2: %3 %4</translation>
    </message>
    <message>
        <source>%1 %2: %3 %4: %5</source>
        <translation>%1 %2: %3 %4: %5</translation>
    </message>
</context>
<context>
    <name>sortie::video::VideoReceiver</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>GStreamer&apos;s %1 is missing: install %2</source>
        <translation>GStreamers %1 fehlt: installieren Sie %2</translation>
    </message>
    <message>
        <source>No %1 decoder: install %2</source>
        <translation>Kein %1-Decoder: installieren Sie %2</translation>
    </message>
    <message>
        <source>The video pipeline could not be built: %1</source>
        <translation>Die Video-Pipeline konnte nicht gebaut werden: %1</translation>
    </message>
    <message>
        <source>No %1: install %2</source>
        <translation>Kein %1: installieren Sie %2</translation>
    </message>
    <message>
        <source>A GStreamer plugin is missing: %1</source>
        <translation>Ein GStreamer-Plugin fehlt: %1</translation>
    </message>
    <message>
        <source>the stream ended</source>
        <translation>der Stream endete</translation>
    </message>
    <message>
        <source>no frame for %1 s</source>
        <translation>%1 s kein Bild</translation>
    </message>
    <message>
        <source>no frame since the last attempt</source>
        <translation>kein Bild seit dem letzten Versuch</translation>
    </message>
    <message>
        <source>nothing received yet</source>
        <translation>noch nichts empfangen</translation>
    </message>
    <message>
        <source>No video URL</source>
        <translation>Keine Video-URL</translation>
    </message>
    <message>
        <source>Video stopped</source>
        <translation>Video angehalten</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>Verbinde mit %1…</translation>
    </message>
    <message>
        <source>Connecting to %1… (%2)</source>
        <translation>Verbinde mit %1… (%2)</translation>
    </message>
    <message>
        <source>%1, %2×%3, %4 decoding (%5)</source>
        <translation>%1, %2×%3, %4-Dekodierung (%5)</translation>
    </message>
    <message>
        <source>hardware</source>
        <translation>Hardware</translation>
    </message>
    <message>
        <source>software</source>
        <translation>Software</translation>
    </message>
    <message>
        <source>No video since %1 (%2); reconnecting</source>
        <translation>Kein Video seit %1 (%2); verbinde neu</translation>
    </message>
</context>
<context>
    <name>sortie::video::VideoRuntime</name>
    <message>
        <source>GStreamer did not start: %1</source>
        <translation>GStreamer ist nicht gestartet: %1</translation>
    </message>
</context>
</TS>
