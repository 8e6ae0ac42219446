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
</context>
<context>
    <name>sortie::ui::Translations</name>
    <message>
        <source>System language</source>
        <translation>Sprache des Systems</translation>
    </message>
</context>
</TS>
