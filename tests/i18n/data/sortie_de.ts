<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<!-- A few words of German for the tests (tst_translations): the real German is resources/i18n/sortie_de.ts. -->
<TS version="2.1" language="de_DE">
<context>
    <name>Main</name>
    <message>
        <source>Login</source>
        <translation>Anmeldung</translation>
    </message>
    <message>
        <source>Mission</source>
        <translation>Einsatz</translation>
    </message>
    <message>
        <source>Live telemetry</source>
        <translation>Live-Telemetrie</translation>
    </message>
</context>
<context>
    <name>sortie::ui::DisplayUnits</name>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>verbunden</translation>
    </message>
</context>
<context>
    <name>sortie::ui::Translations</name>
    <message>
        <source>System language</source>
        <translation>Sprache des Systems</translation>
    </message>
</context>
<context>
    <name>sortie::client::ConnectionController</name>
    <message>
        <source>Ready</source>
        <translation>Bereit</translation>
    </message>
    <message>
        <source>%1 at %2</source>
        <translation>%1 auf %2</translation>
    </message>
</context>
<context>
    <name>sortie::client::MissionController</name>
    <message>
        <source>Opened %1 (version %2).</source>
        <translation>%1 geöffnet (Version %2).</translation>
    </message>
</context>
<context>
    <name>RouteEndurance</name>
    <message>
        <source>No energy profile: choose the vehicle&apos;s profile file</source>
        <translation>Kein Energieprofil: Wählen Sie die Profildatei des Fahrzeugs</translation>
    </message>
</context>
<context>
    <name>TelemetryFieldNames</name>
    <message>
        <source>Ground speed</source>
        <translation>Geschwindigkeit über Grund</translation>
    </message>
</context>
<context>
    <name>sortie::ui::ElevationProfileView</name>
    <message>
        <source>lowest clearance %1</source>
        <translation>geringster Abstand %1</translation>
    </message>
    <message>
        <source>clearance unknown</source>
        <translation>Abstand unbekannt</translation>
    </message>
</context>
<context>
    <name>sortie::ui::OfflineTileSource</name>
    <message>
        <source>Land outlines: Natural Earth</source>
        <translation>Landumrisse: Natural Earth</translation>
    </message>
</context>
<context>
    <name>NumberField</name>
    <message>
        <source>From %1 to %2</source>
        <translation>Von %1 bis %2</translation>
    </message>
</context>
</TS>
