<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es">
<context>
    <name>ActionEditor</name>
    <message>
        <source>The selected waypoints have different actions: these are the first one&apos;s. An edit applies where they match; an added action goes to all.</source>
        <translation>Los waypoints seleccionados tienen acciones distintas: estas son las del primero. Una modificación se aplica donde coinciden; una acción añadida va a todos.</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Quitar</translation>
    </message>
    <message>
        <source>Sent by the server; kept and sent back unchanged.</source>
        <translation>Enviada por el servidor; se conserva y se devuelve sin cambios.</translation>
    </message>
    <message>
        <source>Add action</source>
        <translation>Añadir acción</translation>
    </message>
    <message>
        <source>Remove all</source>
        <translation>Quitar todas</translation>
    </message>
</context>
<context>
    <name>ActionVariants</name>
    <message>
        <source>%1 is either on or off</source>
        <translation>%1 solo puede estar activado o desactivado</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not one of its choices</source>
        <translation>%1: «%2» no es una de sus opciones</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation>%1: «%2» no es un número</translation>
    </message>
    <message>
        <source>%1: %2 is not a whole number</source>
        <translation>%1: %2 no es un número entero</translation>
    </message>
    <message>
        <source>%1: %2 is below %3 %4</source>
        <translation>%1: %2 es menor que %3 %4</translation>
    </message>
    <message>
        <source>%1: %2 is above %3 %4</source>
        <translation>%1: %2 es mayor que %3 %4</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Cámara</translation>
    </message>
    <message>
        <source>Take a photo</source>
        <translation>Tomar una foto</translation>
    </message>
    <message>
        <source>Start video</source>
        <translation>Iniciar vídeo</translation>
    </message>
    <message>
        <source>Stop video</source>
        <translation>Detener vídeo</translation>
    </message>
    <message>
        <source>Toggle video</source>
        <translation>Alternar vídeo</translation>
    </message>
    <message>
        <source>Photos by distance</source>
        <translation>Fotos por distancia</translation>
    </message>
    <message>
        <source>Every</source>
        <translation>Cada</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>Shots (0: until stopped)</source>
        <translation>Disparos (0: hasta detener)</translation>
    </message>
    <message>
        <source>Start after</source>
        <translation>Empezar tras</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <source>Photos by time</source>
        <translation>Fotos por tiempo</translation>
    </message>
    <message>
        <source>Wait</source>
        <translation>Espera</translation>
    </message>
    <message>
        <source>For</source>
        <translation>Durante</translation>
    </message>
    <message>
        <source>Until the operator continues</source>
        <translation>Hasta que el operador continúe</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Rumbo</translation>
    </message>
    <message>
        <source>From the course</source>
        <translation>Respecto a la trayectoria</translation>
    </message>
    <message>
        <source>Point of interest</source>
        <translation>Punto de interés</translation>
    </message>
    <message>
        <source>Latitude</source>
        <translation>Latitud</translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation>Longitud</translation>
    </message>
    <message>
        <source>Altitude</source>
        <translation>Altitud</translation>
    </message>
    <message>
        <source>Altitude type</source>
        <translation>Tipo de altitud</translation>
    </message>
    <message>
        <source>Above ground (AGL)</source>
        <translation>Sobre el terreno (AGL)</translation>
    </message>
    <message>
        <source>Above sea level (AMSL)</source>
        <translation>Sobre el nivel del mar (AMSL)</translation>
    </message>
    <message>
        <source>Gimbal and zoom</source>
        <translation>Gimbal y zoom</translation>
    </message>
    <message>
        <source>Tilt (90: down)</source>
        <translation>Inclinación (90: abajo)</translation>
    </message>
    <message>
        <source>Roll</source>
        <translation>Alabeo</translation>
    </message>
    <message>
        <source>Yaw</source>
        <translation>Guiñada</translation>
    </message>
    <message>
        <source>Zoom level</source>
        <translation>Nivel de zoom</translation>
    </message>
    <message>
        <source>Panorama</source>
        <translation>Panorámica</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Ángulo</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Paso</translation>
    </message>
    <message>
        <source>Pause per step</source>
        <translation>Pausa por paso</translation>
    </message>
    <message>
        <source>Rotation speed</source>
        <translation>Velocidad de giro</translation>
    </message>
    <message>
        <source>°/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <source>Clockwise</source>
        <translation>Sentido horario</translation>
    </message>
    <message>
        <source>Video</source>
        <translation>Vídeo</translation>
    </message>
    <message>
        <source>Set servo</source>
        <translation>Fijar servo</translation>
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
        <translation>Repetir servo</translation>
    </message>
    <message>
        <source>Cycle time</source>
        <translation>Tiempo de ciclo</translation>
    </message>
    <message>
        <source>Repeats</source>
        <translation>Repeticiones</translation>
    </message>
    <message>
        <source>Switch to hover (VTOL)</source>
        <translation>Pasar a vuelo estacionario (VTOL)</translation>
    </message>
    <message>
        <source>Switch to fixed-wing</source>
        <translation>Pasar a ala fija</translation>
    </message>
    <message>
        <source>Lidar recording</source>
        <translation>Grabación lidar</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>Grabación</translation>
    </message>
    <message>
        <source>Lidar calibration</source>
        <translation>Calibración lidar</translation>
    </message>
    <message>
        <source>Distance</source>
        <translation>Distancia</translation>
    </message>
    <message>
        <source>Times</source>
        <translation>Veces</translation>
    </message>
    <message>
        <source>Hop</source>
        <translation>Salto</translation>
    </message>
    <message>
        <source>Descent altitude</source>
        <translation>Altitud de descenso</translation>
    </message>
    <message>
        <source>Drop payload</source>
        <translation>Soltar carga</translation>
    </message>
    <message>
        <source>Descent speed</source>
        <translation>Velocidad de descenso</translation>
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
        <translation>geocerca de la ruta</translation>
    </message>
    <message>
        <source>the open route</source>
        <translation>la ruta abierta</translation>
    </message>
    <message>
        <source>%1 (kept as %2)</source>
        <translation>%1 (se conservó como %2)</translation>
    </message>
    <message>
        <source>drawn</source>
        <translation>dibujada</translation>
    </message>
    <message>
        <source>server</source>
        <translation>servidor</translation>
    </message>
    <message>
        <source>file</source>
        <translation>archivo</translation>
    </message>
    <message>
        <source>server zone %1, edited here</source>
        <translation>zona del servidor %1, editada aquí</translation>
    </message>
    <message>
        <source>today</source>
        <translation>hoy</translation>
    </message>
    <message>
        <source>yesterday</source>
        <translation>ayer</translation>
    </message>
    <message numerus="yes">
        <source>%n day(s) ago</source>
        <translation>
            <numerusform>hace %n día</numerusform>
            <numerusform>hace %n días</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>AirspaceRule</name>
    <message>
        <source>floor %1, ceiling %2</source>
        <translation>base %1, techo %2</translation>
    </message>
    <message>
        <source>at %1</source>
        <translation>a %1</translation>
    </message>
    <message>
        <source>from %1 to %2</source>
        <translation>de %1 a %2</translation>
    </message>
    <message>
        <source>; its height there is unknown (no terrain data), so it counts as inside</source>
        <translation>; allí se desconoce su altura (sin datos de terreno), así que cuenta como dentro</translation>
    </message>
    <message>
        <source>Leg %1 passes within %2 of %3 &apos;%4&apos; (buffer %5).</source>
        <translation>El tramo %1 pasa a menos de %2 de %3 «%4» (margen de aviso %5).</translation>
    </message>
    <message>
        <source>exclusion zone</source>
        <translation>la zona de exclusión</translation>
    </message>
    <message>
        <source>the edge of inclusion zone</source>
        <translation>el borde de la zona de inclusión</translation>
    </message>
    <message>
        <source>Leg %1 enters &apos;%2&apos; %3 (%4)</source>
        <translation>El tramo %1 entra en «%2» %3 (%4)</translation>
    </message>
    <message>
        <source>Leg %1 leaves &apos;%2&apos; %3 (%4)</source>
        <translation>El tramo %1 sale de «%2» %3 (%4)</translation>
    </message>
    <message>
        <source>Message: %1</source>
        <translation>Mensaje: %1</translation>
    </message>
    <message>
        <source>Reason: %1.</source>
        <translation>Motivo: %1.</translation>
    </message>
    <message>
        <source>Authority: %1.</source>
        <translation>Autoridad: %1.</translation>
    </message>
    <message>
        <source>Applies: %1.</source>
        <translation>Se aplica: %1.</translation>
    </message>
    <message>
        <source>Leg %1 enters the prohibited zone &apos;%2&apos; (%3, volume %4) %5 (%6)</source>
        <translation>El tramo %1 entra en la zona prohibida «%2» (%3, volumen %4) %5 (%6)</translation>
    </message>
    <message>
        <source>Leg %1 enters &apos;%2&apos; (%3, volume %4) %5 (%6), which needs an authorisation; none is recorded</source>
        <translation>El tramo %1 entra en «%2» (%3, volumen %4) %5 (%6), que requiere una autorización; no hay ninguna registrada</translation>
    </message>
    <message>
        <source>Leg %1 enters &apos;%2&apos; (%3, volume %4) %5 (%6) under authorisation %7</source>
        <translation>El tramo %1 entra en «%2» (%3, volumen %4) %5 (%6) con la autorización %7</translation>
    </message>
    <message>
        <source>Leg %1 enters the conditional zone &apos;%2&apos; (%3, volume %4) %5 (%6)</source>
        <translation>El tramo %1 entra en la zona condicionada «%2» (%3, volumen %4) %5 (%6)</translation>
    </message>
    <message>
        <source>Leg %1 passes through &apos;%2&apos; (%3, volume %4) %5 (%6), a zone with no restriction</source>
        <translation>El tramo %1 pasa por «%2» (%3, volumen %4) %5 (%6), una zona sin restricciones</translation>
    </message>
</context>
<context>
    <name>AlertBanner</name>
    <message>
        <source>Too close: %1</source>
        <translation>Demasiado cerca: %1</translation>
    </message>
    <message>
        <source>Airspace: %1</source>
        <translation>Espacio aéreo: %1</translation>
    </message>
    <message>
        <source>Return home</source>
        <translation>Volver al origen</translation>
    </message>
</context>
<context>
    <name>AlgorithmDefinition</name>
    <message>
        <source>%1 must be set</source>
        <translation>%1 debe tener un valor</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1: «%2» no es un número</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a whole number</source>
        <translation>%1: «%2» no es un número entero</translation>
    </message>
    <message>
        <source>%1: %2 is below the minimum of %3</source>
        <translation>%1: %2 es menor que el mínimo de %3</translation>
    </message>
    <message>
        <source>%1: %2 is above the maximum of %3</source>
        <translation>%1: %2 es mayor que el máximo de %3</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is neither true nor false</source>
        <translation>%1: «%2» no es ni true ni false</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not one of its choices</source>
        <translation>%1: «%2» no es una de sus opciones</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; does not have the expected form</source>
        <translation>%1: «%2» no tiene la forma esperada</translation>
    </message>
</context>
<context>
    <name>AreaScanPlanner</name>
    <message>
        <source>The camera needs a positive sensor size, focal length and image size.</source>
        <translation>La cámara necesita un tamaño de sensor, una distancia focal y un tamaño de imagen positivos.</translation>
    </message>
    <message>
        <source>Overlaps must be between 0 and 95 %.</source>
        <translation>Los solapes deben estar entre 0 y 95 %.</translation>
    </message>
    <message>
        <source>The scan altitude (or ground sample distance) must be positive.</source>
        <translation>La altitud del escaneo (o la distancia de muestreo, GSD) debe ser positiva.</translation>
    </message>
    <message>
        <source>The turnaround distance must not be negative.</source>
        <translation>La distancia de viraje no debe ser negativa.</translation>
    </message>
</context>
<context>
    <name>AtomicFile</name>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>No se puede escribir %1: %2</translation>
    </message>
</context>
<context>
    <name>AutosaveDirectory</name>
    <message>
        <source>Cannot create the autosave folder %1</source>
        <translation>No se puede crear la carpeta de guardado automático %1</translation>
    </message>
</context>
<context>
    <name>AutosaveRecord</name>
    <message>
        <source>the autosave holds no &quot;%1&quot; route</source>
        <translation>el guardado automático no contiene ninguna ruta «%1»</translation>
    </message>
    <message>
        <source>the &quot;%1&quot; document holds %2 routes, not one</source>
        <translation>el documento «%1» contiene %2 rutas, no una</translation>
    </message>
    <message>
        <source>not a Sortie autosave (&quot;format&quot; is not &quot;sortie-autosave&quot;)</source>
        <translation>no es un guardado automático de Sortie («format» no es «sortie-autosave»)</translation>
    </message>
    <message>
        <source>autosave format version %1 is not one this Sortie reads (1)</source>
        <translation>esta versión de Sortie no lee la versión %1 del formato de guardado automático (lee la 1)</translation>
    </message>
    <message>
        <source>&quot;savedAt&quot; is not a date and time</source>
        <translation>«savedAt» no es una fecha y hora</translation>
    </message>
</context>
<context>
    <name>AutosaveWriter</name>
    <message>
        <source>Cannot remove %1: %2</source>
        <translation>No se puede eliminar %1: %2</translation>
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
        <translation>%1: %2 no contiene ningún certificado PEM</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is neither a SHA-256 fingerprint (64 hex digits) nor a certificate file</source>
        <translation>%1: «%2» no es una huella SHA-256 (64 dígitos hexadecimales) ni un archivo de certificado</translation>
    </message>
</context>
<context>
    <name>Checklist</name>
    <message>
        <source>unknown key &quot;%1&quot;</source>
        <translation>clave desconocida «%1»</translation>
    </message>
    <message>
        <source>an item the operator ticks has no &quot;check&quot;; leave it out</source>
        <translation>un elemento que marca el operador no lleva «check»; quítelo</translation>
    </message>
    <message>
        <source>an item to tick needs a &quot;title&quot;</source>
        <translation>un elemento para marcar necesita un «title»</translation>
    </message>
    <message>
        <source>&quot;%1&quot; takes no minimum</source>
        <translation>«%1» no admite mínimo</translation>
    </message>
    <message>
        <source>%1 is outside %2..%3</source>
        <translation>%1 está fuera de %2..%3</translation>
    </message>
    <message>
        <source>&quot;%1&quot; needs a &quot;minimum&quot;</source>
        <translation>«%1» necesita un «minimum»</translation>
    </message>
    <message>
        <source>an empty list holds nothing back; say &quot;required&quot;: false instead</source>
        <translation>una lista vacía no retiene nada; escriba &quot;required&quot;: false en su lugar</translation>
    </message>
    <message>
        <source>Sortie&apos;s default checklist</source>
        <translation>Lista de comprobación predeterminada de Sortie</translation>
    </message>
    <message>
        <source>Propellers fitted and tight</source>
        <translation>Hélices montadas y apretadas</translation>
    </message>
    <message>
        <source>Take-off area clear of people</source>
        <translation>Zona de despegue libre de personas</translation>
    </message>
    <message>
        <source>Payload and battery secured</source>
        <translation>Carga útil y batería aseguradas</translation>
    </message>
    <message>
        <source>a checklist needs at least one item</source>
        <translation>una lista de comprobación necesita al menos un elemento</translation>
    </message>
</context>
<context>
    <name>ChecklistPanel</name>
    <message>
        <source>Pre-flight checklist</source>
        <translation>Lista de comprobación previa al vuelo</translation>
    </message>
    <message>
        <source>Ready to arm and fly the mission</source>
        <translation>Listo para armar y volar la misión</translation>
    </message>
    <message>
        <source>Ready to arm; Auto waits</source>
        <translation>Listo para armar; Auto espera</translation>
    </message>
    <message>
        <source>Not ready to arm: %1 of %2 pass</source>
        <translation>No está listo para armar: se cumplen %1 de %2</translation>
    </message>
    <message>
        <source>Not used, Sortie&apos;s default instead: %1</source>
        <translation>No se usa; en su lugar, la predeterminada de Sortie: %1</translation>
    </message>
    <message>
        <source>Sortie&apos;s default; write your own in %1</source>
        <translation>La predeterminada de Sortie; escriba la suya en %1</translation>
    </message>
    <message>
        <source>Choose a vehicle to see its checklist.</source>
        <translation>Elija un vehículo para ver su lista de comprobación.</translation>
    </message>
    <message>
        <source>%1 (advisory)</source>
        <translation>%1 (orientativo)</translation>
    </message>
    <message>
        <source>Read again</source>
        <translation>Volver a leer</translation>
    </message>
    <message>
        <source>Read the checklist files again after editing them (the ticks are cleared)</source>
        <translation>Volver a leer los archivos de listas tras editarlos (las marcas se borran)</translation>
    </message>
</context>
<context>
    <name>CommandBar</name>
    <message>
        <source>Are you sure?</source>
        <translation>¿Está seguro?</translation>
    </message>
    <message numerus="yes">
        <source>To %n ticked vehicle(s): %1</source>
        <translation>
            <numerusform>A %n vehículo marcado: %1</numerusform>
            <numerusform>A los %n vehículos marcados: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Untick all</source>
        <translation>Desmarcar todos</translation>
    </message>
    <message>
        <source>Arm</source>
        <translation>Armar</translation>
    </message>
    <message>
        <source>Disarm</source>
        <translation>Desarmar</translation>
    </message>
    <message>
        <source>Take off</source>
        <translation>Despegar</translation>
    </message>
    <message>
        <source>Climb to %1 m above home</source>
        <translation>Subir a %1 m sobre el origen</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>Fly the uploaded mission</source>
        <translation>Volar la misión subida</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Reanudar</translation>
    </message>
    <message>
        <source>Land</source>
        <translation>Aterrizar</translation>
    </message>
    <message>
        <source>Return home</source>
        <translation>Volver al origen</translation>
    </message>
    <message>
        <source>Go here…</source>
        <translation>Ir aquí…</translation>
    </message>
    <message>
        <source>Then click on the map where the vehicle should fly</source>
        <translation>Después haga clic en el mapa donde debe volar el vehículo</translation>
    </message>
    <message>
        <source>Choose a vehicle on the map or in the list; tick several to command them together.</source>
        <translation>Elija un vehículo en el mapa o en la lista; marque varios para darles órdenes a la vez.</translation>
    </message>
    <message>
        <source>The checklist does not pass</source>
        <translation>La lista de comprobación no se cumple</translation>
    </message>
    <message>
        <source>%1 is held back on %2 by:</source>
        <translation>%1 queda retenido en %2 por:</translation>
    </message>
    <message>
        <source>Send it anyway? The override and these reasons go into the command log and the flight log.</source>
        <translation>¿Enviarlo de todos modos? La anulación y estos motivos quedan en el registro de órdenes y en el registro de vuelo.</translation>
    </message>
    <message>
        <source>Send anyway</source>
        <translation>Enviar de todos modos</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Checklist ✓</source>
        <translation>Lista ✓</translation>
    </message>
    <message numerus="yes">
        <source>Checklist: %n to do</source>
        <translation>
            <numerusform>Lista: %n pendiente</numerusform>
            <numerusform>Lista: %n pendientes</numerusform>
        </translation>
    </message>
    <message>
        <source>The pre-flight checklist: Arm and Auto wait for its required items</source>
        <translation>La lista de comprobación previa al vuelo: Armar y Auto esperan a sus elementos obligatorios</translation>
    </message>
    <message>
        <source>Gamepad</source>
        <translation>Mando</translation>
    </message>
    <message>
        <source>Gamepad buttons as commands, each asking first (by default Start arms, X pauses, Y lands, B returns home). %1</source>
        <translation>Botones del mando como órdenes, cada una pregunta antes (por defecto Start arma, X pausa, Y aterriza, B vuelve a casa). %1</translation>
    </message>
</context>
<context>
    <name>CommandLogView</name>
    <message>
        <source>Command log</source>
        <translation>Registro de órdenes</translation>
    </message>
</context>
<context>
    <name>ComparisonPanel</name>
    <message>
        <source>Compare with a route</source>
        <translation>Comparar con una ruta</translation>
    </message>
    <message>
        <source>Routes (*.sortie *.plan *.waypoints *.wpl *.txt)</source>
        <translation>Rutas (*.sortie *.plan *.waypoints *.wpl *.txt)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Compare with route…</source>
        <translation>Comparar con ruta…</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Borrar</translation>
    </message>
    <message>
        <source>leg</source>
        <translation>tramo</translation>
    </message>
    <message>
        <source>samples</source>
        <translation>muestras</translation>
    </message>
    <message>
        <source>cross-track max</source>
        <translation>desvío lateral máx.</translation>
    </message>
    <message>
        <source>mean</source>
        <translation>media</translation>
    </message>
    <message>
        <source>altitude max</source>
        <translation>altitud máx.</translation>
    </message>
    <message>
        <source>reached</source>
        <translation>alcanzado</translation>
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
        <translation>la cámara %1 no tiene tamaño de sensor, distancia focal ni resolución</translation>
    </message>
    <message>
        <source>the minimum number of images and the cell must be positive</source>
        <translation>el número mínimo de imágenes y la celda deben ser positivos</translation>
    </message>
    <message>
        <source>its position is not a place</source>
        <translation>su posición no es un lugar</translation>
    </message>
    <message>
        <source>its height above the ground is not known</source>
        <translation>no se conoce su altura sobre el suelo</translation>
    </message>
    <message>
        <source>taken %1 m above the ground: on the ground, not surveying</source>
        <translation>tomada a %1 m sobre el suelo: en tierra, no durante el levantamiento</translation>
    </message>
    <message>
        <source>its heading is not known</source>
        <translation>no se conoce su rumbo</translation>
    </message>
    <message>
        <source>no photo has a position, a height above the ground and a heading</source>
        <translation>ninguna foto tiene posición, altura sobre el suelo y rumbo</translation>
    </message>
    <message>
        <source>PROJ does not know EPSG:%1 (is proj-data installed?)</source>
        <translation>PROJ no conoce EPSG:%1 (¿está instalado proj-data?)</translation>
    </message>
    <message>
        <source>no transformation between WGS-84 and EPSG:%1</source>
        <translation>no hay transformación entre WGS-84 y EPSG:%1</translation>
    </message>
    <message>
        <source>it cannot be placed in EPSG:%1</source>
        <translation>no se puede situar en EPSG:%1</translation>
    </message>
    <message>
        <source>no photo could be placed in EPSG:%1</source>
        <translation>ninguna foto se pudo situar en EPSG:%1</translation>
    </message>
    <message>
        <source>the photos span %1 × %2 m: %3 m cells would make %4 million, more than the %5 million a raster may hold; choose a larger cell</source>
        <translation>las fotos abarcan %1 × %2 m: celdas de %3 m darían %4 millones, más que los %5 millones que admite un ráster; elija una celda mayor</translation>
    </message>
    <message>
        <source>GDAL cannot make a %1 × %2 raster in memory</source>
        <translation>GDAL no puede crear un ráster de %1 × %2 en memoria</translation>
    </message>
    <message>
        <source>GDAL cannot rasterise the footprints</source>
        <translation>GDAL no puede rasterizar las huellas</translation>
    </message>
    <message>
        <source>the photos cover no area</source>
        <translation>las fotos no cubren ningún área</translation>
    </message>
    <message>
        <source>GDAL cannot rasterise the surveyed area</source>
        <translation>GDAL no puede rasterizar el área levantada</translation>
    </message>
    <message>
        <source>GDAL cannot read its raster back</source>
        <translation>GDAL no puede volver a leer su ráster</translation>
    </message>
    <message>
        <source>GDAL cannot make the holes&apos; layer</source>
        <translation>GDAL no puede crear la capa de huecos</translation>
    </message>
    <message>
        <source>GDAL cannot trace the holes</source>
        <translation>GDAL no puede trazar los huecos</translation>
    </message>
    <message>
        <source>no raster to write</source>
        <translation>no hay ráster que escribir</translation>
    </message>
    <message>
        <source>GDAL has no GeoTIFF driver</source>
        <translation>GDAL no tiene controlador GeoTIFF</translation>
    </message>
    <message>
        <source>%1 cannot be written</source>
        <translation>%1 no se puede escribir</translation>
    </message>
    <message>
        <source>%1 cannot be put in place</source>
        <translation>%1 no se puede poner en su sitio</translation>
    </message>
    <message>
        <source>Re-fly the gaps</source>
        <translation>Volver a volar los huecos</translation>
    </message>
    <message>
        <source>The hole of %1 m² at %2, %3 is not in the route: %4</source>
        <translation>El hueco de %1 m² en %2, %3 no está en la ruta: %4</translation>
    </message>
</context>
<context>
    <name>CoverageSweep</name>
    <message>
        <source>An area scan needs a polygon of at least 3 vertices.</source>
        <translation>Un escaneo de área necesita un polígono de al menos 3 vértices.</translation>
    </message>
    <message>
        <source>Polygon vertex %1 is not a valid position.</source>
        <translation>El vértice %1 del polígono no es una posición válida.</translation>
    </message>
    <message>
        <source>The polygon spans more than 100 km; split it into smaller scans.</source>
        <translation>El polígono abarca más de 100 km; divídalo en escaneos más pequeños.</translation>
    </message>
    <message>
        <source>The scan polygon crosses itself (edges %1 and %2).</source>
        <translation>El polígono del escaneo se corta a sí mismo (lados %1 y %2).</translation>
    </message>
    <message>
        <source>The scan polygon has no area.</source>
        <translation>El polígono del escaneo no tiene área.</translation>
    </message>
    <message>
        <source>The distance between passes must be positive.</source>
        <translation>La distancia entre pasadas debe ser positiva.</translation>
    </message>
    <message>
        <source>The scan would need %1 transects; raise the altitude or lower the side overlap.</source>
        <translation>El escaneo necesitaría %1 transectos; aumente la altitud o reduzca el solape lateral.</translation>
    </message>
    <message>
        <source>The scan yields no transects: the polygon is too narrow.</source>
        <translation>El escaneo no produce ningún transecto: el polígono es demasiado estrecho.</translation>
    </message>
</context>
<context>
    <name>CustomZoneFile</name>
    <message>
        <source>drawn on the map</source>
        <translation>dibujada en el mapa</translation>
    </message>
</context>
<context>
    <name>DemFolderSource</name>
    <message>
        <source>DEM folder (%1)</source>
        <translation>carpeta de MDE (%1)</translation>
    </message>
</context>
<context>
    <name>DemOpener</name>
    <message>
        <source>%1: no such file or folder</source>
        <translation>%1: no existe ese archivo ni esa carpeta</translation>
    </message>
</context>
<context>
    <name>DemRaster</name>
    <message>
        <source>the raster is not georeferenced (no geotransform)</source>
        <translation>el ráster no está georreferenciado (sin geotransformación)</translation>
    </message>
    <message>
        <source>the raster states no coordinate reference system</source>
        <translation>el ráster no indica ningún sistema de referencia de coordenadas</translation>
    </message>
    <message>
        <source>no transformation from WGS-84 into the raster&apos;s CRS: %1</source>
        <translation>no hay transformación de WGS-84 al SRC del ráster: %1</translation>
    </message>
    <message>
        <source>PROJ gave no reason</source>
        <translation>PROJ no dio ningún motivo</translation>
    </message>
    <message>
        <source>the raster&apos;s extent cannot be expressed in WGS-84 degrees</source>
        <translation>la extensión del ráster no se puede expresar en grados WGS-84</translation>
    </message>
    <message>
        <source>its heights are ellipsoidal and converting them to AMSL needs the EGM96 geoid: %1</source>
        <translation>sus alturas son elipsoidales y convertirlas a AMSL requiere el geoide EGM96: %1</translation>
    </message>
</context>
<context>
    <name>Egm96Geoid</name>
    <message>
        <source>the EGM96 geoid grid %1 is missing (Debian: install proj-data): ellipsoidal heights cannot be converted to AMSL</source>
        <translation>falta la rejilla del geoide EGM96 %1 (Debian: instale proj-data): las alturas elipsoidales no se pueden convertir a AMSL</translation>
    </message>
    <message>
        <source>the EGM96 geoid grid %1 cannot be used: %2</source>
        <translation>no se puede usar la rejilla del geoide EGM96 %1: %2</translation>
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
        <translation>%1 debe ser un número positivo</translation>
    </message>
    <message>
        <source>reserve must be a fraction from 0 up to (not including) 1</source>
        <translation>reserve debe ser una fracción desde 0 hasta 1 (sin incluirlo)</translation>
    </message>
    <message>
        <source>acceleration must be a positive number</source>
        <translation>acceleration debe ser un número positivo</translation>
    </message>
    <message>
        <source>expected &quot;file&quot;, &quot;server&quot; or &quot;fit&quot;</source>
        <translation>se esperaba «file», «server» o «fit»</translation>
    </message>
</context>
<context>
    <name>FleetRoutesList</name>
    <message>
        <source>Routes</source>
        <translation>Rutas</translation>
    </message>
    <message>
        <source>%1 flight</source>
        <translation>%1 de vuelo</translation>
    </message>
    <message>
        <source>%1 flight · %2 flown · %3 left</source>
        <translation>%1 de vuelo · volado %2 · quedan %3</translation>
    </message>
</context>
<context>
    <name>FlightLogExport</name>
    <message>
        <source>Flight log %1</source>
        <translation>Registro de vuelo %1</translation>
    </message>
</context>
<context>
    <name>FlightLogInfo</name>
    <message>
        <source>
  %1 (%2%3%4): %5 samples</source>
        <translation>
  %1 (%2%3%4): %5 muestras</translation>
    </message>
</context>
<context>
    <name>FlightLogSettingsDialog</name>
    <message>
        <source>Flight logs</source>
        <translation>Registros de vuelo</translation>
    </message>
    <message>
        <source>Folder</source>
        <translation>Carpeta</translation>
    </message>
    <message>
        <source>Holds</source>
        <translation>Contiene</translation>
    </message>
    <message>
        <source>Recording to</source>
        <translation>Grabando en</translation>
    </message>
    <message>
        <source>not recording</source>
        <translation>sin grabar</translation>
    </message>
    <message>
        <source>A log up to (MB)</source>
        <translation>Un registro hasta (MB)</translation>
    </message>
    <message>
        <source>The folder up to (MB)</source>
        <translation>La carpeta hasta (MB)</translation>
    </message>
    <message>
        <source>0: no limit. A log over its size continues in a new part; beyond the folder&apos;s size the oldest logs are deleted, never the one being written.</source>
        <translation>0: sin límite. Un registro que supera su tamaño continúa en una nueva parte; por encima del tamaño de la carpeta se eliminan los registros más antiguos, nunca el que se está escribiendo.</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Aplicar</translation>
    </message>
</context>
<context>
    <name>GdalDataset</name>
    <message>
        <source>no such file</source>
        <translation>no existe ese archivo</translation>
    </message>
    <message>
        <source>GDAL knows no raster format for this file</source>
        <translation>GDAL no conoce ningún formato ráster para este archivo</translation>
    </message>
    <message>
        <source>the file has no raster band</source>
        <translation>el archivo no tiene ninguna banda ráster</translation>
    </message>
    <message>
        <source>GeoTIFF (COG), SRTM .hgt, DTED, ESRI ASCII grid, ERDAS Imagine, ESRI .bil/.flt, USGS DEM, PNG, JPEG, JPEG 2000 and .vrt mosaics of them</source>
        <translation>GeoTIFF (COG), SRTM .hgt, DTED, cuadrícula ASCII de ESRI, ERDAS Imagine, ESRI .bil/.flt, USGS DEM, PNG, JPEG, JPEG 2000 y mosaicos .vrt de ellos</translation>
    </message>
    <message>
        <source>a GDAL VRT (driver VRT) under a name that is not .vrt: Sortie reads %1</source>
        <translation>un VRT de GDAL (controlador VRT) con un nombre que no es .vrt: Sortie lee %1</translation>
    </message>
    <message>
        <source>GDAL reads this file with its %1 driver, which Sortie does not use for the operator&apos;s rasters: it reads %2</source>
        <translation>GDAL lee este archivo con su controlador %1, que Sortie no usa para los ráster del operador: lee %2</translation>
    </message>
    <message>
        <source>its overview file %1 is not a GeoTIFF (GDAL: %2)</source>
        <translation>su archivo de vistas generales %1 no es un GeoTIFF (GDAL: %2)</translation>
    </message>
    <message>
        <source>a raw band (VRTRawRasterBand) is not read</source>
        <translation>una banda en bruto (VRTRawRasterBand) no se lee</translation>
    </message>
    <message>
        <source>a pixel function&apos;s code is not run</source>
        <translation>el código de una función de píxel no se ejecuta</translation>
    </message>
    <message>
        <source>its source %1 is not a local file</source>
        <translation>su fuente %1 no es un archivo local</translation>
    </message>
    <message>
        <source>VRTs nested more than %1 deep</source>
        <translation>VRT anidados a más de %1 niveles</translation>
    </message>
    <message>
        <source>%1: a VRT of more than %2 MiB</source>
        <translation>%1: un VRT de más de %2 MiB</translation>
    </message>
    <message>
        <source>the VRT is not XML</source>
        <translation>el VRT no es XML</translation>
    </message>
    <message>
        <source>network access is off: Sortie reads local files only (%1)</source>
        <translation>el acceso a la red está desactivado: Sortie solo lee archivos locales (%1)</translation>
    </message>
</context>
<context>
    <name>GdalDemSource</name>
    <message>
        <source>DEM (%1)</source>
        <translation>MDE (%1)</translation>
    </message>
</context>
<context>
    <name>GeoZone</name>
    <message>
        <source>daily</source>
        <translation>a diario</translation>
    </message>
    <message>
        <source>always</source>
        <translation>siempre</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 a %2</translation>
    </message>
    <message>
        <source>from %1</source>
        <translation>desde %1</translation>
    </message>
    <message>
        <source>until %1</source>
        <translation>hasta %1</translation>
    </message>
    <message>
        <source>ask %1 before</source>
        <translation>solicitar con %1 de antelación</translation>
    </message>
    <message>
        <source>Prohibited</source>
        <translation>Prohibida</translation>
    </message>
    <message>
        <source>Authorisation needed</source>
        <translation>Requiere autorización</translation>
    </message>
    <message>
        <source>Conditions apply</source>
        <translation>Con condiciones</translation>
    </message>
    <message>
        <source>Information only</source>
        <translation>Solo información</translation>
    </message>
</context>
<context>
    <name>Geotag</name>
    <message>
        <source>the track holds no positions</source>
        <translation>la traza no contiene posiciones</translation>
    </message>
    <message>
        <source>taken at %1, %2 s before the track starts (%3)</source>
        <translation>tomada a las %1, %2 s antes de que empiece la traza (%3)</translation>
    </message>
    <message>
        <source>taken at %1, %2 s after the track ends (%3)</source>
        <translation>tomada a las %1, %2 s después de que termine la traza (%3)</translation>
    </message>
    <message>
        <source>taken at %1, in a gap of %2 s in the track (from %3 to %4; at most %5 s is bridged)</source>
        <translation>tomada a las %1, en un hueco de %2 s de la traza (de %3 a %4; se salvan como mucho %5 s)</translation>
    </message>
    <message>
        <source>it holds no capture time (EXIF DateTimeOriginal or XMP exif:DateTimeOriginal)</source>
        <translation>no contiene la hora de captura (EXIF DateTimeOriginal o XMP exif:DateTimeOriginal)</translation>
    </message>
    <message>
        <source>its copy cannot be made in %1: %2</source>
        <translation>no se puede hacer su copia en %1: %2</translation>
    </message>
    <message>
        <source>its copy cannot be put in place: %1</source>
        <translation>su copia no se puede poner en su sitio: %1</translation>
    </message>
    <message>
        <source>%1 is not a folder of photos that can be read</source>
        <translation>%1 no es una carpeta de fotos que se pueda leer</translation>
    </message>
    <message>
        <source>%1 holds no photos (.jpg, .jpeg, .tif, .tiff, .dng)</source>
        <translation>%1 no contiene fotos (.jpg, .jpeg, .tif, .tiff, .dng)</translation>
    </message>
    <message>
        <source>no folder given for the geotagged copies</source>
        <translation>no se ha indicado ninguna carpeta para las copias georreferenciadas</translation>
    </message>
    <message>
        <source>%1: the folder for the geotagged copies cannot be made</source>
        <translation>%1: no se puede crear la carpeta para las copias georreferenciadas</translation>
    </message>
    <message>
        <source>%1 is the photos&apos; own folder: the copies go elsewhere, the originals are never changed</source>
        <translation>%1 es la propia carpeta de las fotos: las copias van a otro sitio, los originales nunca se modifican</translation>
    </message>
    <message>
        <source>exiv2 cannot read it (%1)</source>
        <translation>exiv2 no puede leerlo (%1)</translation>
    </message>
    <message>
        <source>exiv2 cannot open it</source>
        <translation>exiv2 no puede abrirlo</translation>
    </message>
    <message>
        <source>its OffsetTimeOriginal &quot;%1&quot; is no time zone offset (±HH:MM)</source>
        <translation>su OffsetTimeOriginal «%1» no es un desfase de zona horaria (±HH:MM)</translation>
    </message>
    <message>
        <source>no valid position to write</source>
        <translation>no hay una posición válida que escribir</translation>
    </message>
    <message>
        <source>exiv2 cannot write its tags (%1)</source>
        <translation>exiv2 no puede escribir sus etiquetas (%1)</translation>
    </message>
    <message>
        <source>%1 is not a GPX file (its root element is &lt;%2&gt;, not &lt;gpx&gt;)</source>
        <translation>%1 no es un archivo GPX (su elemento raíz es &lt;%2&gt;, no &lt;gpx&gt;)</translation>
    </message>
    <message>
        <source>%1: a track point needs lat (-90 to 90) and lon (-180 to 180) in degrees, not lat=&quot;%2&quot; lon=&quot;%3&quot;</source>
        <translation>%1: un punto de la traza necesita lat (de -90 a 90) y lon (de -180 a 180) en grados, no lat=&quot;%2&quot; lon=&quot;%3&quot;</translation>
    </message>
    <message>
        <source>%1: &lt;ele&gt; &quot;%2&quot; is no elevation in metres</source>
        <translation>%1: &lt;ele&gt; «%2» no es una altitud en metros</translation>
    </message>
    <message>
        <source>%1: &lt;time&gt; &quot;%2&quot; is no UTC time (YYYY-MM-DDThh:mm:ssZ)</source>
        <translation>%1: &lt;time&gt; «%2» no es una hora UTC (YYYY-MM-DDThh:mm:ssZ)</translation>
    </message>
    <message>
        <source>%1: the track point has no &lt;time&gt;, so no photo can be matched to it</source>
        <translation>%1: el punto de la traza no tiene &lt;time&gt;, así que no se le puede asignar ninguna foto</translation>
    </message>
    <message>
        <source>%1 is not a readable GPX file: %2</source>
        <translation>%1 no es un archivo GPX legible: %2</translation>
    </message>
    <message>
        <source>%1 is not a GPX file (no &lt;gpx&gt; element)</source>
        <translation>%1 no es un archivo GPX (no tiene elemento &lt;gpx&gt;)</translation>
    </message>
    <message>
        <source>%1 holds no track points (&lt;trkpt&gt;)</source>
        <translation>%1 no contiene puntos de traza (&lt;trkpt&gt;)</translation>
    </message>
    <message>
        <source>%1 has no such vehicle</source>
        <translation>%1 no tiene ese vehículo</translation>
    </message>
    <message>
        <source>%1: vehicle %2 reported no position</source>
        <translation>%1: el vehículo %2 no informó de ninguna posición</translation>
    </message>
    <message>
        <source>exiv2 wrote its tags but they do not read back</source>
        <translation>exiv2 escribió las etiquetas pero no las vuelve a leer</translation>
    </message>
    <message>
        <source>exiv2 wrote a copy it cannot read back (%1)</source>
        <translation>exiv2 escribió una copia que no puede volver a leer (%1)</translation>
    </message>
    <message>
        <source>no photo the vehicle reported taking matches its time (a shot before or after the flight, or another camera&apos;s)</source>
        <translation>ninguna foto que el vehículo dijo tomar coincide con su hora (una toma antes o después del vuelo, o de otra cámara)</translation>
    </message>
</context>
<context>
    <name>GlanceBar</name>
    <message>
        <source>The connection to the server</source>
        <translation>La conexión con el servidor</translation>
    </message>
    <message>
        <source>The vehicle chosen in the fly view, else the first</source>
        <translation>El vehículo elegido en la vista de vuelo; si no, el primero</translation>
    </message>
    <message>
        <source>Its GPS: the fix and the satellites in view</source>
        <translation>Su GPS: el tipo de posición y los satélites a la vista</translation>
    </message>
    <message>
        <source>Its battery, against the low and critical levels</source>
        <translation>Su batería, frente a los niveles bajo y crítico</translation>
    </message>
    <message>
        <source>Its link: how often its position arrives</source>
        <translation>Su enlace: con qué frecuencia llega su posición</translation>
    </message>
</context>
<context>
    <name>HciConnection</name>
    <message>
        <source>type %1</source>
        <translation>tipo %1</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>No answer from %1 within %2: check the address and the network</source>
        <translation>Sin respuesta de %1 en %2: compruebe la dirección y la red</translation>
    </message>
    <message>
        <source>The server at %1 closed the connection</source>
        <translation>El servidor en %1 cerró la conexión</translation>
    </message>
    <message>
        <source>The connection was closed by the application</source>
        <translation>La aplicación cerró la conexión</translation>
    </message>
    <message>
        <source>Disconnected from %1</source>
        <translation>Desconectado de %1</translation>
    </message>
    <message>
        <source>%1 refused the connection</source>
        <translation>%1 rechazó la conexión</translation>
    </message>
    <message>
        <source>The host in %1 cannot be found</source>
        <translation>No se encuentra el host de %1</translation>
    </message>
    <message>
        <source>Cannot reach %1: %2</source>
        <translation>No se puede acceder a %1: %2</translation>
    </message>
    <message>
        <source>Connection to %1 lost: %2</source>
        <translation>Conexión con %1 perdida: %2</translation>
    </message>
    <message>
        <source>%1 got no answer: %2</source>
        <translation>%1 no obtuvo respuesta: %2</translation>
    </message>
    <message>
        <source>%1 is not an HCI message</source>
        <translation>%1 no es un mensaje HCI</translation>
    </message>
    <message>
        <source>%1 not sent: not connected to the server</source>
        <translation>%1 no enviado: no hay conexión con el servidor</translation>
    </message>
    <message>
        <source>%1 not sent: missing %2</source>
        <translation>%1 no enviado: falta %2</translation>
    </message>
    <message>
        <source>No answer to %1 within %2</source>
        <translation>Sin respuesta a %1 en %2</translation>
    </message>
    <message>
        <source>%1 at byte %2: %3</source>
        <translation>%1 en el byte %2: %3</translation>
    </message>
    <message>
        <source>%1 with instance id -1 is not a notification</source>
        <translation>%1 con id de instancia -1 no es una notificación</translation>
    </message>
    <message>
        <source>%1 for instance id %2, which no request waits for (answered after its timeout?)</source>
        <translation>%1 para el id de instancia %2, que ninguna solicitud espera (¿respondida tras agotarse su tiempo?)</translation>
    </message>
    <message>
        <source>The server answered %1 with %2 instead of %3</source>
        <translation>El servidor respondió a %1 con %2 en lugar de %3</translation>
    </message>
    <message>
        <source>Not connected to %1 over TLS: %2</source>
        <translation>Sin conexión con %1 por TLS: %2</translation>
    </message>
    <message>
        <source>The TLS handshake with %1 failed (%2): does it speak TLS on that port?</source>
        <translation>El establecimiento de TLS con %1 falló (%2): ¿habla TLS en ese puerto?</translation>
    </message>
    <message>
        <source>%1 accepted the connection but did not begin TLS within %2: is it a plain HCI server?</source>
        <translation>%1 aceptó la conexión pero no inició TLS en %2: ¿es un servidor HCI sin cifrar?</translation>
    </message>
</context>
<context>
    <name>HciElevationSource</name>
    <message>
        <source>UgCS server</source>
        <translation>Servidor UgCS</translation>
    </message>
</context>
<context>
    <name>HciError</name>
    <message>
        <source>The server&apos;s licence does not allow this (%1)</source>
        <translation>La licencia del servidor no lo permite (%1)</translation>
    </message>
    <message>
        <source>The server&apos;s licence does not allow this</source>
        <translation>La licencia del servidor no lo permite</translation>
    </message>
    <message>
        <source>The server speaks HCI protocol %1; Sortie speaks 2.0%2</source>
        <translation>El servidor usa el protocolo HCI %1; Sortie usa el 2.0%2</translation>
    </message>
    <message>
        <source>The server refused the request (error %1)</source>
        <translation>El servidor rechazó la solicitud (error %1)</translation>
    </message>
    <message>
        <source>The server refused the request without a reason</source>
        <translation>El servidor rechazó la solicitud sin indicar el motivo</translation>
    </message>
    <message>
        <source>no error</source>
        <translation>sin error</translation>
    </message>
    <message>
        <source> (code %1)</source>
        <translation> (código %1)</translation>
    </message>
</context>
<context>
    <name>HciRouteMapper</name>
    <message>
        <source>Route &quot;%1&quot;, segment %2: %3</source>
        <translation>Ruta «%1», segmento %2: %3</translation>
    </message>
</context>
<context>
    <name>HciRoutePass</name>
    <message>
        <source>a RoutePass event names the object type &quot;%1&quot;</source>
        <translation>un evento RoutePass indica el tipo de objeto «%1»</translation>
    </message>
    <message>
        <source>RoutePass %1: the event carries no RoutePass</source>
        <translation>RoutePass %1: el evento no contiene ningún RoutePass</translation>
    </message>
    <message>
        <source>RoutePass %1 names no vehicle</source>
        <translation>RoutePass %1 no indica ningún vehículo</translation>
    </message>
    <message>
        <source>RoutePass %1 has no waypoint count</source>
        <translation>RoutePass %1 no tiene número de waypoints</translation>
    </message>
    <message>
        <source>RoutePass %1: waypoint index %2 is outside the route&apos;s %3 waypoints</source>
        <translation>RoutePass %1: el índice de waypoint %2 está fuera de los %3 waypoints de la ruta</translation>
    </message>
</context>
<context>
    <name>HciSegmentMapper</name>
    <message>
        <source>the waypoint has no figure point</source>
        <translation>el waypoint no tiene punto de figura</translation>
    </message>
    <message>
        <source>the waypoint&apos;s position is out of range</source>
        <translation>la posición del waypoint está fuera de rango</translation>
    </message>
    <message>
        <source>An area scan&apos;s %1: %2 It keeps Sortie&apos;s default.</source>
        <translation>%1 de un escaneo de área: %2 Se conserva el valor predeterminado de Sortie.</translation>
    </message>
    <message>
        <source>An area scan came without a camera; Sortie&apos;s default camera (%1) was assumed.</source>
        <translation>Un escaneo de área llegó sin cámara; se supuso la cámara predeterminada de Sortie (%1).</translation>
    </message>
    <message>
        <source>A %1 segment could not be read as one (%2); it is kept as the server sent it.</source>
        <translation>Un segmento %1 no se pudo leer como tal (%2); se conserva tal como lo envió el servidor.</translation>
    </message>
    <message>
        <source>An area scan without a polygon of three corners is kept as the server sent it.</source>
        <translation>Un escaneo de área sin un polígono de tres esquinas se conserva tal como lo envió el servidor.</translation>
    </message>
</context>
<context>
    <name>HciSession</name>
    <message>
        <source> not sent: </source>
        <translation> no enviado: </translation>
    </message>
    <message>
        <source>the connection to the server is being re-established</source>
        <translation>se está restableciendo la conexión con el servidor</translation>
    </message>
    <message>
        <source>not logged in to a server</source>
        <translation>no hay sesión iniciada en ningún servidor</translation>
    </message>
    <message>
        <source>The server sent nothing while %1 waited (%2); the link seems dead</source>
        <translation>El servidor no envió nada mientras %1 esperaba (%2); el enlace parece caído</translation>
    </message>
    <message>
        <source>The server speaks HCI protocol %1.%2; Sortie speaks %3.%4</source>
        <translation>El servidor usa el protocolo HCI %1.%2; Sortie usa el %3.%4</translation>
    </message>
    <message>
        <source>The server rejected the login &apos;%1&apos;: %2</source>
        <translation>El servidor rechazó el inicio de sesión «%1»: %2</translation>
    </message>
</context>
<context>
    <name>HciVehicleLink</name>
    <message>
        <source>%1: cannot take control of %2: %3</source>
        <translation>%1: no se puede tomar el control de %2: %3</translation>
    </message>
    <message>
        <source>%1: the server sent no result for this vehicle</source>
        <translation>%1: el servidor no envió ningún resultado para este vehículo</translation>
    </message>
    <message>
        <source>there is no such flight mode</source>
        <translation>no existe ese modo de vuelo</translation>
    </message>
    <message>
        <source>Segment %1: %2</source>
        <translation>Segmento %1: %2</translation>
    </message>
    <message>
        <source>the server could not process it</source>
        <translation>el servidor no pudo procesarlo</translation>
    </message>
    <message>
        <source>Sortie upload to %1</source>
        <translation>Subida de Sortie a %1</translation>
    </message>
    <message>
        <source>route processing: %1</source>
        <translation>procesamiento de la ruta: %1</translation>
    </message>
    <message>
        <source>upload: the mission was not prepared by the UgCS server</source>
        <translation>subida: el servidor UgCS no preparó la misión</translation>
    </message>
    <message>
        <source>upload: %1</source>
        <translation>subida: %1</translation>
    </message>
    <message>
        <source>upload: cannot take control of %1: %2</source>
        <translation>subida: no se puede tomar el control de %1: %2</translation>
    </message>
    <message>
        <source>a UgCS server does not read a vehicle&apos;s mission back</source>
        <translation>un servidor UgCS no lee de vuelta la misión de un vehículo</translation>
    </message>
    <message>
        <source>%1: parameters are set in the vehicle profile on the UgCS server</source>
        <translation>%1: los parámetros se fijan en el perfil de vehículo del servidor UgCS</translation>
    </message>
</context>
<context>
    <name>HgtTile</name>
    <message>
        <source>%1 bytes is not an SRTM tile (2884802 bytes for 3″ 1201×1201, 25934402 for 1″ 3601×3601); the file is truncated or not a .hgt tile</source>
        <translation>%1 bytes no es una tesela SRTM (2884802 bytes para 3″ 1201×1201, 25934402 para 1″ 3601×3601); el archivo está truncado o no es una tesela .hgt</translation>
    </message>
    <message>
        <source>height %1 m at row %2, column %3 is not a terrain height; the file is corrupt</source>
        <translation>la altura %1 m en la fila %2, columna %3 no es una altura de terreno; el archivo está dañado</translation>
    </message>
</context>
<context>
    <name>HgtTileSource</name>
    <message>
        <source>%1: no such file or folder</source>
        <translation>%1: no existe el archivo o la carpeta</translation>
    </message>
    <message>
        <source>%1: not an SRTM tile name (NxxEyyy.hgt names the tile&apos;s south-west corner)</source>
        <translation>%1: no es un nombre de tesela SRTM (NxxEyyy.hgt indica la esquina suroeste de la tesela)</translation>
    </message>
    <message>
        <source>SRTM tiles (%1)</source>
        <translation>Teselas SRTM (%1)</translation>
    </message>
    <message>
        <source>%1: cannot be mapped: %2</source>
        <translation>%1: no se puede mapear en memoria: %2</translation>
    </message>
</context>
<context>
    <name>IndexedDemSource</name>
    <message>
        <source>%1: no rasters</source>
        <translation>%1: no hay rásteres</translation>
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
        <translation>Ningún vehículo elegido</translation>
    </message>
    <message>
        <source>Altitude AGL</source>
        <translation>Altitud AGL</translation>
    </message>
    <message>
        <source>Altitude AMSL</source>
        <translation>Altitud AMSL</translation>
    </message>
    <message>
        <source>Ground speed</source>
        <translation>Velocidad respecto al suelo</translation>
    </message>
    <message>
        <source>Vertical speed</source>
        <translation>Velocidad vertical</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Rumbo</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Batería</translation>
    </message>
    <message>
        <source>GPS</source>
        <translation>GPS</translation>
    </message>
    <message>
        <source>fix %1, %2 satellites</source>
        <translation>fix %1, %2 satélites</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modo</translation>
    </message>
    <message>
        <source>Armed</source>
        <translation>Armado</translation>
    </message>
    <message>
        <source>ARMED</source>
        <translation>ARMADO</translation>
    </message>
    <message>
        <source>disarmed</source>
        <translation>desarmado</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Enlace</translation>
    </message>
    <message>
        <source> (no data)</source>
        <translation> (sin datos)</translation>
    </message>
    <message>
        <source>%1, %2 Hz</source>
        <translation>%1, %2 Hz</translation>
    </message>
    <message>
        <source>Flight time</source>
        <translation>Tiempo de vuelo</translation>
    </message>
    <message>
        <source>To home</source>
        <translation>Al origen</translation>
    </message>
    <message>
        <source>Mission</source>
        <translation>Misión</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Restante</translation>
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
        <translation>se esperaba un objeto, se encontró %1</translation>
    </message>
    <message>
        <source>missing required key &quot;%1&quot;</source>
        <translation>falta la clave obligatoria «%1»</translation>
    </message>
    <message>
        <source>expected an array, found %1</source>
        <translation>se esperaba un array, se encontró %1</translation>
    </message>
    <message>
        <source>expected at least %1 elements, found %2</source>
        <translation>se esperaban al menos %1 elementos, se encontraron %2</translation>
    </message>
    <message>
        <source>expected a number, found %1</source>
        <translation>se esperaba un número, se encontró %1</translation>
    </message>
    <message>
        <source>the number is not finite</source>
        <translation>el número no es finito</translation>
    </message>
    <message>
        <source>expected an integer, found %1</source>
        <translation>se esperaba un entero, se encontró %1</translation>
    </message>
    <message>
        <source>expected true or false, found %1</source>
        <translation>se esperaba true o false, se encontró %1</translation>
    </message>
    <message>
        <source>expected a string, found %1</source>
        <translation>se esperaba una cadena, se encontró %1</translation>
    </message>
    <message>
        <source>not valid JSON: %1</source>
        <translation>JSON no válido: %1</translation>
    </message>
    <message>
        <source>unknown value &quot;%1&quot;</source>
        <translation>valor desconocido «%1»</translation>
    </message>
</context>
<context>
    <name>KmlFormat</name>
    <message>
        <source>bad coordinate &quot;%1&quot;: expected longitude,latitude[,altitude]</source>
        <translation>coordenada incorrecta «%1»: se esperaba longitud,latitud[,altitud]</translation>
    </message>
    <message>
        <source>bad coordinate &quot;%1&quot;: not a number</source>
        <translation>coordenada incorrecta «%1»: no es un número</translation>
    </message>
    <message>
        <source>coordinate &quot;%1&quot; is out of range</source>
        <translation>la coordenada «%1» está fuera de rango</translation>
    </message>
    <message>
        <source>a boundary needs at least 3 distinct points, found %1</source>
        <translation>un contorno necesita al menos 3 puntos distintos, se encontraron %1</translation>
    </message>
    <message>
        <source>not valid KML: %1</source>
        <translation>KML no válido: %1</translation>
    </message>
    <message>
        <source>this LineString is open, so it encloses no area; close it (last point = first) to use it as a boundary</source>
        <translation>este LineString está abierto, así que no encierra ningún área; ciérrelo (último punto = primero) para usarlo como contorno</translation>
    </message>
    <message>
        <source>this Placemark has no Polygon (with an outerBoundaryIs LinearRing) or closed LineString</source>
        <translation>este Placemark no tiene ningún Polygon (con un LinearRing outerBoundaryIs) ni un LineString cerrado</translation>
    </message>
    <message>
        <source>the document has no Polygon or closed LineString</source>
        <translation>el documento no tiene ningún Polygon ni LineString cerrado</translation>
    </message>
    <message>
        <source>The file holds %1 closed shapes; the one at line %2 was imported.</source>
        <translation>El archivo contiene %1 formas cerradas; se importó la de la línea %2.</translation>
    </message>
    <message>
        <source>Flight path</source>
        <translation>Trayectoria de vuelo</translation>
    </message>
    <message>
        <source>Flight path, part %1</source>
        <translation>Trayectoria de vuelo, parte %1</translation>
    </message>
</context>
<context>
    <name>KmlZones</name>
    <message>
        <source>bad coordinate &quot;%1&quot;: expected longitude,latitude[,altitude]</source>
        <translation>coordenada incorrecta «%1»: se esperaba longitud,latitud[,altitud]</translation>
    </message>
    <message>
        <source>coordinate &quot;%1&quot; is out of range</source>
        <translation>la coordenada «%1» está fuera de rango</translation>
    </message>
    <message>
        <source>a boundary needs at least 3 distinct coordinates, found %1</source>
        <translation>un contorno necesita al menos 3 coordenadas distintas, se encontraron %1</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>línea %1: %2</translation>
    </message>
    <message>
        <source>line %1: a polygon with two outer boundaries</source>
        <translation>línea %1: un polígono con dos contornos exteriores</translation>
    </message>
    <message>
        <source>line %1: an inner boundary before the outer one</source>
        <translation>línea %1: un contorno interior antes del exterior</translation>
    </message>
    <message>
        <source>Placemark %1</source>
        <translation>Placemark %1</translation>
    </message>
    <message>
        <source>Placemark &apos;%1&apos;</source>
        <translation>Placemark «%1»</translation>
    </message>
    <message>
        <source>a Polygon without an outer boundary</source>
        <translation>un Polygon sin contorno exterior</translation>
    </message>
    <message>
        <source>%1 (line %2) was left out: %3</source>
        <translation>Se omitió %1 (línea %2): %3</translation>
    </message>
    <message>
        <source>not well-formed KML: %1</source>
        <translation>KML mal formado: %1</translation>
    </message>
</context>
<context>
    <name>LandOutlines</name>
    <message>
        <source>the land outline file is not compressed data</source>
        <translation>el archivo de contornos de tierra no contiene datos comprimidos</translation>
    </message>
    <message>
        <source>the land outline file does not start with %1</source>
        <translation>el archivo de contornos de tierra no empieza por %1</translation>
    </message>
    <message>
        <source>the land outline file is truncated at its polygon count</source>
        <translation>el archivo de contornos de tierra está truncado en su número de polígonos</translation>
    </message>
    <message>
        <source>the land outline file is truncated in polygon %1</source>
        <translation>el archivo de contornos de tierra está truncado en el polígono %1</translation>
    </message>
    <message>
        <source>the land outline file is truncated in polygon %1, ring %2</source>
        <translation>el archivo de contornos de tierra está truncado en el polígono %1, anillo %2</translation>
    </message>
    <message>
        <source>the built-in land outlines (%1) are missing</source>
        <translation>faltan los contornos de tierra integrados (%1)</translation>
    </message>
</context>
<context>
    <name>LoginPage</name>
    <message>
        <source>Connect to a UgCS server</source>
        <translation>Conectar a un servidor UgCS</translation>
    </message>
    <message>
        <source>Server (host:port)</source>
        <translation>Servidor (host:puerto)</translation>
    </message>
    <message>
        <source>Host name or address and HCI port of the UgCS server</source>
        <translation>Nombre de host o dirección y puerto HCI del servidor UgCS</translation>
    </message>
    <message>
        <source>User</source>
        <translation>Usuario</translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Contraseña</translation>
    </message>
    <message>
        <source>Remember the password on this computer</source>
        <translation>Recordar la contraseña en este equipo</translation>
    </message>
    <message>
        <source>Kept in this computer&apos;s keyring for this server and user, never in a file</source>
        <translation>Se guarda en el llavero de este equipo para este servidor y usuario, nunca en un archivo</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Conectar</translation>
    </message>
    <message>
        <source>Log in (Enter in the password field)</source>
        <translation>Iniciar sesión (Intro en el campo de contraseña)</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Desconectar</translation>
    </message>
    <message>
        <source>Logged in as %1 at %2.</source>
        <translation>Sesión iniciada como %1 en %2.</translation>
    </message>
    <message>
        <source>%1…</source>
        <translation>%1…</translation>
    </message>
    <message>
        <source>Secure (TLS)</source>
        <translation>Segura (TLS)</translation>
    </message>
    <message>
        <source>For a server behind a TLS terminator: the password and everything else travel encrypted</source>
        <translation>Para un servidor detrás de un terminador TLS: la contraseña y todo lo demás viajan cifrados</translation>
    </message>
    <message>
        <source>Send in clear</source>
        <translation>Enviar sin cifrar</translation>
    </message>
    <message>
        <source>Do not connect</source>
        <translation>No conectar</translation>
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
        <translation>Inicio de sesión</translation>
    </message>
    <message>
        <source>Mission</source>
        <translation>Misión</translation>
    </message>
    <message>
        <source>Live telemetry</source>
        <translation>Telemetría en vivo</translation>
    </message>
    <message>
        <source>Map…</source>
        <translation>Mapa…</translation>
    </message>
    <message>
        <source>Choose the map source (Ctrl+M)</source>
        <translation>Elegir la fuente del mapa (Ctrl+M)</translation>
    </message>
    <message>
        <source>Offline…</source>
        <translation>Sin conexión…</translation>
    </message>
    <message>
        <source>Download the web map of an area for work without a network</source>
        <translation>Descargar el mapa web de una zona para trabajar sin red</translation>
    </message>
    <message>
        <source>Logs…</source>
        <translation>Registros…</translation>
    </message>
    <message>
        <source>Where flight logs are recorded, and how much they may take</source>
        <translation>Dónde se graban los registros de vuelo y cuánto pueden ocupar</translation>
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
        <translation>Cambiar entre unidades métricas e imperiales</translation>
    </message>
    <message>
        <source>Keyboard shortcuts (F1)</source>
        <translation>Atajos de teclado (F1)</translation>
    </message>
    <message>
        <source>The language of Sortie, applied at once</source>
        <translation>Idioma de Sortie; se aplica al instante</translation>
    </message>
    <message>
        <source>Display…</source>
        <translation>Pantalla…</translation>
    </message>
    <message>
        <source>Units, language and colours</source>
        <translation>Unidades, idioma y colores</translation>
    </message>
    <message>
        <source>Units</source>
        <translation>Unidades</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Idioma</translation>
    </message>
    <message>
        <source>Colours</source>
        <translation>Colores</translation>
    </message>
    <message>
        <source>The system&apos;s colours, light, dark, or high contrast for sunlight</source>
        <translation>Los colores del sistema, claro, oscuro o alto contraste para la luz del sol</translation>
    </message>
</context>
<context>
    <name>MapPane</name>
    <message>
        <source>Zoom in (+, wheel)</source>
        <translation>Acercar (+, rueda)</translation>
    </message>
    <message>
        <source>Zoom out (−, wheel)</source>
        <translation>Alejar (−, rueda)</translation>
    </message>
</context>
<context>
    <name>MapSourceDialog</name>
    <message>
        <source>Map source</source>
        <translation>Fuente del mapa</translation>
    </message>
    <message>
        <source>Offline base map (land outlines, always available)</source>
        <translation>Mapa base sin conexión (contornos de tierra, siempre disponible)</translation>
    </message>
    <message>
        <source>Web tiles from a URL template</source>
        <translation>Teselas web desde una plantilla de URL</translation>
    </message>
    <message>
        <source>{z}, {x} and {y} (or {-y}) are replaced per tile; {s} by a subdomain</source>
        <translation>{z}, {x} e {y} (o {-y}) se sustituyen en cada tesela; {s}, por un subdominio</translation>
    </message>
    <message>
        <source>MBTiles file (offline raster tiles)</source>
        <translation>Archivo MBTiles (teselas ráster sin conexión)</translation>
    </message>
    <message>
        <source>/path/to/area.mbtiles</source>
        <translation>/ruta/a/zona.mbtiles</translation>
    </message>
    <message>
        <source>Orthophoto over the base map (GeoTIFF or any raster GDAL reads, any CRS)</source>
        <translation>Ortofoto sobre el mapa base (GeoTIFF o cualquier ráster que lea GDAL, cualquier CRS)</translation>
    </message>
    <message>
        <source>/path/to/orthophoto.tif (empty: none)</source>
        <translation>/ruta/a/ortofoto.tif (vacío: ninguna)</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Opacidad</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Terrain: a DEM file (GeoTIFF, .hgt, ...) or a folder of them</source>
        <translation>Terreno: un archivo DEM (GeoTIFF, .hgt, ...) o una carpeta de ellos</translation>
    </message>
    <message>
        <source>/path/to/dem.tif or /path/to/dem-folder (empty: none)</source>
        <translation>/ruta/a/dem.tif o /ruta/a/carpeta-dem (vacío: ninguno)</translation>
    </message>
    <message>
        <source>Orthophoto</source>
        <translation>Ortofoto</translation>
    </message>
    <message>
        <source>Rasters (*.tif *.tiff *.jp2 *.vrt *.img *.ecw *.sid *.png *.jpg)</source>
        <translation>Rásteres (*.tif *.tiff *.jp2 *.vrt *.img *.ecw *.sid *.png *.jpg)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Terrain model (DEM)</source>
        <translation>Modelo del terreno (MDE)</translation>
    </message>
    <message>
        <source>Elevation rasters (*.tif *.tiff *.hgt *.vrt *.dt0 *.dt1 *.dt2 *.asc *.img *.bil *.flt *.dem)</source>
        <translation>Rásteres de elevación (*.tif *.tiff *.hgt *.vrt *.dt0 *.dt1 *.dt2 *.asc *.img *.bil *.flt *.dem)</translation>
    </message>
    <message>
        <source>A folder of terrain models (DEM tiles)</source>
        <translation>Una carpeta de modelos del terreno (teselas MDE)</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Examinar…</translation>
    </message>
    <message>
        <source>File…</source>
        <translation>Archivo…</translation>
    </message>
    <message>
        <source>Folder…</source>
        <translation>Carpeta…</translation>
    </message>
</context>
<context>
    <name>MavlinkExport</name>
    <message>
        <source>MAVLink has no stop-and-turn or bank-turn waypoints: they were written as plain waypoints.</source>
        <translation>MAVLink no tiene waypoints de parada y giro ni de giro inclinado: se escribieron como waypoints simples.</translation>
    </message>
    <message>
        <source>Waypoint %1: %2 has no MAVLink equivalent and was left out.</source>
        <translation>Waypoint %1: %2 no tiene equivalente en MAVLink y se omitió.</translation>
    </message>
    <message>
        <source>a servo action without its servo and PWM</source>
        <translation>una acción de servo sin su servo y su PWM</translation>
    </message>
    <message>
        <source>a repeated servo without its count and cycle time</source>
        <translation>una repetición de servo sin su número y su tiempo de ciclo</translation>
    </message>
    <message>
        <source>waiting for the operator</source>
        <translation>la espera al operador</translation>
    </message>
    <message>
        <source>a heading relative to the course</source>
        <translation>un rumbo relativo a la trayectoria</translation>
    </message>
    <message>
        <source>toggling video</source>
        <translation>la alternancia de vídeo</translation>
    </message>
    <message>
        <source>the series&apos; start delay</source>
        <translation>el retardo de inicio de la serie</translation>
    </message>
    <message>
        <source>the series&apos; shot count and start delay</source>
        <translation>el número de disparos y el retardo de inicio de la serie</translation>
    </message>
    <message>
        <source>a panorama</source>
        <translation>una panorámica</translation>
    </message>
    <message>
        <source>Waypoint %1: the gimbal&apos;s %2 was not set and is written as 0° (MAVLink has no &quot;unchanged&quot;).</source>
        <translation>Waypoint %1: en el gimbal no se fijó %2 y se escribe como 0° (MAVLink no tiene «sin cambios»).</translation>
    </message>
    <message>
        <source>a zoom level</source>
        <translation>un nivel de zoom</translation>
    </message>
    <message>
        <source>%1 was left out: %2</source>
        <translation>Se omitió %1: %2</translation>
    </message>
    <message>
        <source>it cannot be planned</source>
        <translation>no se puede planificar</translation>
    </message>
    <message>
        <source>Segments without a MAVLink equivalent (circle, perimeter...) were written as the waypoints Sortie plans for them.</source>
        <translation>Los segmentos sin equivalente en MAVLink (círculo, perímetro...) se escribieron como los waypoints que Sortie planifica para ellos.</translation>
    </message>
    <message>
        <source>Area scan %1 was left out: %2</source>
        <translation>Se omitió el escaneo de área %1: %2</translation>
    </message>
    <message>
        <source>Area scan %1 was written as %2 waypoints with distance triggering.</source>
        <translation>El escaneo de área %1 se escribió como %2 waypoints con disparo por distancia.</translation>
    </message>
    <message>
        <source>tilt</source>
        <extracomment>A gimbal&apos;s axis, listed in &quot;the gimbal&apos;s %2 was not set&quot; (tilt, roll, yaw).</extracomment>
        <translation>inclinación</translation>
    </message>
    <message>
        <source>roll</source>
        <extracomment>A gimbal&apos;s axis, listed in &quot;the gimbal&apos;s %2 was not set&quot; (tilt, roll, yaw).</extracomment>
        <translation>alabeo</translation>
    </message>
    <message>
        <source>yaw</source>
        <extracomment>A gimbal&apos;s axis, listed in &quot;the gimbal&apos;s %2 was not set&quot; (tilt, roll, yaw).</extracomment>
        <translation>guiñada</translation>
    </message>
</context>
<context>
    <name>MbTilesFile</name>
    <message>
        <source>No MBTiles file is set.</source>
        <translation>No se ha indicado ningún archivo MBTiles.</translation>
    </message>
    <message>
        <source>The MBTiles file %1 does not exist.</source>
        <translation>El archivo MBTiles %1 no existe.</translation>
    </message>
    <message>
        <source>Cannot open the MBTiles file %1: %2</source>
        <translation>No se puede abrir el archivo MBTiles %1: %2</translation>
    </message>
    <message>
        <source>%1 is not an MBTiles file Sortie can write: %2</source>
        <translation>%1 no es un archivo MBTiles en el que Sortie pueda escribir: %2</translation>
    </message>
    <message>
        <source>%1 is not an MBTiles file (it has no tiles table).</source>
        <translation>%1 no es un archivo MBTiles (no tiene tabla de teselas).</translation>
    </message>
    <message>
        <source>The MBTiles file %1 has no readable metadata: %2</source>
        <translation>El archivo MBTiles %1 no tiene metadatos legibles: %2</translation>
    </message>
    <message>
        <source>Cannot write to the MBTiles file %1: %2</source>
        <translation>No se puede escribir en el archivo MBTiles %1: %2</translation>
    </message>
    <message>
        <source>Cannot write the metadata of %1: %2</source>
        <translation>No se pueden escribir los metadatos de %1: %2</translation>
    </message>
    <message>
        <source>Reading tile %1 failed: %2</source>
        <translation>Falló la lectura de la tesela %1: %2</translation>
    </message>
    <message>
        <source>Writing %1 tiles to %2 failed: %3</source>
        <translation>Falló la escritura de %1 teselas en %2: %3</translation>
    </message>
    <message>
        <source>Reading the tiles of %1 failed: %2</source>
        <translation>Falló la lectura de las teselas de %1: %2</translation>
    </message>
    <message>
        <source>The MBTiles file %1 has more than %2 metadata rows.</source>
        <translation>El archivo MBTiles %1 tiene más de %2 filas de metadatos.</translation>
    </message>
    <message>
        <source>stopped: %1</source>
        <translation>detenido: %1</translation>
    </message>
</context>
<context>
    <name>MbTilesMetadata</name>
    <message>
        <source>%1: &apos;%2&apos; is not a zoom level (0 to 30).</source>
        <translation>%1: «%2» no es un nivel de zoom (0 a 30).</translation>
    </message>
    <message>
        <source>bounds: &apos;%1&apos; is not west,south,east,north in degrees.</source>
        <translation>bounds: «%1» no es oeste,sur,este,norte en grados.</translation>
    </message>
    <message>
        <source>minzoom %1 is above maxzoom %2.</source>
        <translation>minzoom %1 es mayor que maxzoom %2.</translation>
    </message>
</context>
<context>
    <name>MissionDifference</name>
    <message numerus="yes">
        <source>the vehicle holds %n waypoint(s), %1 were sent</source>
        <translation>
            <numerusform>el vehículo contiene %n waypoint; se enviaron %1</numerusform>
            <numerusform>el vehículo contiene %n waypoints; se enviaron %1</numerusform>
        </translation>
    </message>
    <message>
        <source>waypoint %1: </source>
        <translation>waypoint %1: </translation>
    </message>
    <message>
        <source>the vehicle holds another position</source>
        <translation>el vehículo contiene otra posición</translation>
    </message>
    <message>
        <source>altitude %1 m, sent %2 m</source>
        <translation>altitud %1 m, enviada %2 m</translation>
    </message>
    <message>
        <source>speed %1 m/s, sent %2 m/s</source>
        <translation>velocidad %1 m/s, enviada %2 m/s</translation>
    </message>
    <message>
        <source>acceptance radius %1 m, sent %2 m</source>
        <translation>radio de aceptación %1 m, enviado %2 m</translation>
    </message>
    <message numerus="yes">
        <source>%n action(s), sent %1</source>
        <translation>
            <numerusform>%n acción, enviadas %1</numerusform>
            <numerusform>%n acciones, enviadas %1</numerusform>
        </translation>
    </message>
    <message>
        <source>action %1 (%2) differs</source>
        <translation>la acción %1 (%2) es distinta</translation>
    </message>
</context>
<context>
    <name>MissionError</name>
    <message>
        <source>(at %1)</source>
        <translation>(en %1)</translation>
    </message>
</context>
<context>
    <name>MissionFiles</name>
    <message>
        <source>cannot open: %1</source>
        <translation>no se puede abrir: %1</translation>
    </message>
    <message>
        <source>unknown file type: use .sortie, .plan, .waypoints, .kml or .kmz</source>
        <translation>tipo de archivo desconocido: use .sortie, .plan, .waypoints, .kml o .kmz</translation>
    </message>
    <message>
        <source>Sortie mission</source>
        <translation>Misión de Sortie</translation>
    </message>
    <message>
        <source>QGroundControl plan</source>
        <translation>Plan de QGroundControl</translation>
    </message>
    <message>
        <source>QGC WPL 110 waypoints</source>
        <translation>Waypoints QGC WPL 110</translation>
    </message>
    <message>
        <source>DJI WPML</source>
        <translation>DJI WPML</translation>
    </message>
    <message>
        <source>a KML file holds a polygon, not a mission: import it as an area-scan boundary</source>
        <translation>un archivo KML contiene un polígono, no una misión: impórtelo como contorno de un escaneo de área</translation>
    </message>
    <message>
        <source>the mission has no route %1 (it has %2)</source>
        <translation>la misión no tiene la ruta %1 (tiene %2)</translation>
    </message>
    <message>
        <source>the mission has no route to write</source>
        <translation>la misión no tiene ninguna ruta que escribir</translation>
    </message>
    <message>
        <source>the mission has %1 routes and a %2 file holds one: choose the route to write (sortie-plan convert --route N), or write .sortie or DJI WPML (.kmz), which hold them all</source>
        <translation>la misión tiene %1 rutas y un archivo %2 contiene una: elija la ruta que escribir (sortie-plan convert --route N) o escriba .sortie o DJI WPML (.kmz), que las contienen todas</translation>
    </message>
    <message>
        <source>Saving route &quot;%1&quot;</source>
        <translation>Guardar la ruta «%1»</translation>
    </message>
    <message>
        <source>cannot write: %1</source>
        <translation>no se puede escribir: %1</translation>
    </message>
    <message>
        <source>the file is larger than %1 MiB</source>
        <translation>el archivo supera los %1 MiB</translation>
    </message>
</context>
<context>
    <name>MissionPage</name>
    <message>
        <source>Zones (%1)</source>
        <translation>Zonas (%1)</translation>
    </message>
    <message>
        <source>Click the centre line (%1 so far)</source>
        <translation>Haga clic en la línea central (%1 hasta ahora)</translation>
    </message>
    <message>
        <source>Click the corners of the area (%1 so far)</source>
        <translation>Haga clic en las esquinas del área (%1 hasta ahora)</translation>
    </message>
    <message>
        <source>Click where it goes</source>
        <translation>Haga clic donde debe ir</translation>
    </message>
    <message>
        <source>Create</source>
        <translation>Crear</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Click the corners (%1 so far), or Shift+drag a box</source>
        <translation>Pulse las esquinas (%1 hasta ahora) o arrastre un rectángulo con Mayús</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Hecho</translation>
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
        <translation>Volver al mapa</translation>
    </message>
    <message>
        <source>The route, the ground and the zones in 3D</source>
        <translation>La ruta, el terreno y las zonas en 3D</translation>
    </message>
</context>
<context>
    <name>NfzConversion</name>
    <message>
        <source>its baseAltitude is not a number</source>
        <translation>su baseAltitude no es un número</translation>
    </message>
    <message>
        <source>its height %1 m is not a height (it must be 0 or more)</source>
        <translation>su altura %1 m no es una altura (debe ser 0 o más)</translation>
    </message>
    <message>
        <source>point %1 of its prism is not a position (latitude and longitude in radians)</source>
        <translation>el punto %1 de su prisma no es una posición (latitud y longitud en radianes)</translation>
    </message>
    <message numerus="yes">
        <source>its prism has %n corner(s); a polygon needs 3</source>
        <translation>
            <numerusform>su prisma tiene %n esquina; un polígono necesita 3</numerusform>
            <numerusform>su prisma tiene %n esquinas; un polígono necesita 3</numerusform>
        </translation>
    </message>
    <message>
        <source>its cone frustum has no centre (baseLatitude, baseLongitude in radians)</source>
        <translation>su tronco de cono no tiene centro (baseLatitude, baseLongitude en radianes)</translation>
    </message>
    <message>
        <source>its cone frustum&apos;s radii (base %1 m, top %2 m) are not a circle</source>
        <translation>los radios de su tronco de cono (base %1 m, parte superior %2 m) no forman un círculo</translation>
    </message>
    <message>
        <source>its cone frustum has two radii but no height</source>
        <translation>su tronco de cono tiene dos radios pero ninguna altura</translation>
    </message>
    <message>
        <source>its floor (%1) and ceiling (%2) are in different references; a server zone has one</source>
        <translation>su base (%1) y su techo (%2) están en referencias distintas; una zona del servidor tiene una sola</translation>
    </message>
    <message>
        <source>its heights are above home; a server zone&apos;s are AMSL or AGL</source>
        <translation>sus alturas son sobre el origen; las de una zona del servidor son AMSL o AGL</translation>
    </message>
    <message>
        <source>it starts from the ground with an AMSL ceiling; give it an AMSL floor or an AGL ceiling</source>
        <translation>empieza en el suelo con un techo AMSL; dele una base AMSL o un techo AGL</translation>
    </message>
    <message>
        <source>NoFlightZone %1</source>
        <translation>NoFlightZone %1</translation>
    </message>
    <message>
        <source>UgCS server, NoFlightZone %1</source>
        <translation>servidor UgCS, NoFlightZone %1</translation>
    </message>
    <message>
        <source>it has both a prism and a cone frustum</source>
        <translation>tiene a la vez un prisma y un tronco de cono</translation>
    </message>
    <message>
        <source>it has no volume (neither a prism nor a cone frustum)</source>
        <translation>no tiene volumen (ni prisma ni tronco de cono)</translation>
    </message>
    <message>
        <source>its ceiling is below its floor</source>
        <translation>su techo está por debajo de su base</translation>
    </message>
    <message>
        <source>the server&apos;s no-fly zones keep vehicles out; an inclusion zone cannot be one</source>
        <translation>las zonas de no vuelo del servidor mantienen fuera a los vehículos; una zona de inclusión no puede ser una de ellas</translation>
    </message>
    <message>
        <source>aerodrome zones are the server&apos;s own; only custom zones are changed</source>
        <translation>las zonas de aeródromo son del propio servidor; solo se modifican las zonas personalizadas</translation>
    </message>
    <message numerus="yes">
        <source>%n ring(s)</source>
        <translation>
            <numerusform>%n anillo</numerusform>
            <numerusform>%n anillos</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>a server zone is one polygon without holes (this one has %n part(s), %1)</source>
        <translation>
            <numerusform>una zona del servidor es un polígono sin huecos (esta tiene %n parte, %1)</numerusform>
            <numerusform>una zona del servidor es un polígono sin huecos (esta tiene %n partes, %1)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>its polygon has %n corner(s); it needs 3</source>
        <translation>
            <numerusform>su polígono tiene %n esquina; necesita 3</numerusform>
            <numerusform>su polígono tiene %n esquinas; necesita 3</numerusform>
        </translation>
    </message>
    <message>
        <source>a cone frustum needs a ceiling</source>
        <translation>un tronco de cono necesita un techo</translation>
    </message>
    <message>
        <source>NoFlightZone %1%2 was left out: %3</source>
        <translation>Se omitió NoFlightZone %1%2: %3</translation>
    </message>
</context>
<context>
    <name>NumberField</name>
    <message>
        <source>Not a number: type it as %1</source>
        <translation>No es un número: escríbalo como %1</translation>
    </message>
    <message>
        <source>From %1 to %2</source>
        <translation>De %1 a %2</translation>
    </message>
    <message>
        <source>At least %1</source>
        <translation>Al menos %1</translation>
    </message>
    <message>
        <source>At most %1</source>
        <translation>Como máximo %1</translation>
    </message>
</context>
<context>
    <name>OfflineMapsDialog</name>
    <message>
        <source>Offline maps</source>
        <translation>Mapas sin conexión</translation>
    </message>
    <message>
        <source>From %1</source>
        <translation>Desde %1</translation>
    </message>
    <message>
        <source>Choose a web tile server in Map source first.</source>
        <translation>Elija primero un servidor de teselas web en Fuente del mapa.</translation>
    </message>
    <message>
        <source>The open route</source>
        <translation>La ruta abierta</translation>
    </message>
    <message>
        <source>and</source>
        <translation>y</translation>
    </message>
    <message>
        <source>m around it</source>
        <translation>m alrededor</translation>
    </message>
    <message>
        <source>The map&apos;s view</source>
        <translation>La vista del mapa</translation>
    </message>
    <message>
        <source>Zoom from</source>
        <translation>Zoom de</translation>
    </message>
    <message>
        <source>to</source>
        <translation>a</translation>
    </message>
    <message>
        <source>Pack file</source>
        <translation>Archivo de paquete</translation>
    </message>
    <message>
        <source>Attribution</source>
        <translation>Atribución</translation>
    </message>
    <message>
        <source>As the provider&apos;s usage policy asks, e.g. © OpenStreetMap contributors</source>
        <translation>Según pida la política de uso del proveedor, p. ej. © colaboradores de OpenStreetMap</translation>
    </message>
    <message>
        <source>Cache only: the map never uses the network (the pack, then the disk cache)</source>
        <translation>Solo caché: el mapa nunca usa la red (primero el paquete, luego la caché en disco)</translation>
    </message>
    <message>
        <source>Download</source>
        <translation>Descargar</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Reanudar</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Detener</translation>
    </message>
    <message>
        <source>Draw an area</source>
        <translation>Dibujar un área</translation>
    </message>
    <message>
        <source>Click its corners on the map, or Shift+drag a box</source>
        <translation>Pulse sus esquinas en el mapa o arrastre un rectángulo con Mayús</translation>
    </message>
</context>
<context>
    <name>OpenQuestion</name>
    <message>
        <source>Unsaved edits</source>
        <translation>Cambios sin guardar</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Guardar</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Descartar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>OrthophotoRenderer</name>
    <message>
        <source>the image is not georeferenced (no CRS or no geotransform)</source>
        <translation>la imagen no está georreferenciada (sin SRC o sin geotransformación)</translation>
    </message>
    <message>
        <source>its extent cannot be placed on the map: %1</source>
        <translation>su extensión no se puede situar en el mapa: %1</translation>
    </message>
    <message>
        <source>PROJ gave no reason</source>
        <translation>PROJ no dio ningún motivo</translation>
    </message>
    <message>
        <source>no memory for a tile</source>
        <translation>no hay memoria para una tesela</translation>
    </message>
    <message>
        <source>%1: tile %2/%3/%4: %5</source>
        <translation>%1: tesela %2/%3/%4: %5</translation>
    </message>
    <message>
        <source>the warp failed</source>
        <translation>la reproyección falló</translation>
    </message>
    <message>
        <source>the warped tile cannot be read</source>
        <translation>la tesela reproyectada no se puede leer</translation>
    </message>
    <message>
        <source>%1: tile size %2 is outside 1..%3</source>
        <translation>%1: el tamaño de tesela %2 está fuera de 1..%3</translation>
    </message>
</context>
<context>
    <name>OutsideDatabase</name>
    <message>
        <source>more than %1 steps</source>
        <translation>más de %1 pasos</translation>
    </message>
    <message>
        <source>more than %1 rows</source>
        <translation>más de %1 filas</translation>
    </message>
    <message>
        <source>SQLite refused the settings a file from outside is read with</source>
        <translation>SQLite rechazó los ajustes con los que se lee un archivo de fuera</translation>
    </message>
</context>
<context>
    <name>PhotosDialog</name>
    <message>
        <source>Photos of the flight</source>
        <translation>Fotos del vuelo</translation>
    </message>
    <message>
        <source>The folder of the flight&apos;s photos</source>
        <translation>La carpeta de las fotos del vuelo</translation>
    </message>
    <message>
        <source>Where the geotagged copies go</source>
        <translation>Dónde van las copias georreferenciadas</translation>
    </message>
    <message>
        <source>Photos</source>
        <translation>Fotos</translation>
    </message>
    <message>
        <source>a folder of JPEG, TIFF or DNG photos</source>
        <translation>una carpeta de fotos JPEG, TIFF o DNG</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Elegir…</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Cámara</translation>
    </message>
    <message>
        <source>Camera clock behind the log (s)</source>
        <translation>Reloj de la cámara tras el registro (s)</translation>
    </message>
    <message>
        <source>Seconds added to each photo&apos;s time: how far the camera&apos;s clock is behind the log&apos;s (GNSS) time</source>
        <translation>Segundos sumados a la hora de cada foto: cuánto va el reloj de la cámara por detrás de la hora (GNSS) del registro</translation>
    </message>
    <message>
        <source>Place photos</source>
        <translation>Situar las fotos</translation>
    </message>
    <message>
        <source>Holes, largest first (shaded on the map):</source>
        <translation>Huecos, el mayor primero (sombreados en el mapa):</translation>
    </message>
    <message>
        <source>Not placed:</source>
        <translation>Sin situar:</translation>
    </message>
    <message>
        <source>Write geotagged copies…</source>
        <translation>Escribir copias georreferenciadas…</translation>
    </message>
    <message>
        <source>Re-fly the gaps</source>
        <translation>Volver a volar los huecos</translation>
    </message>
    <message>
        <source>A route of an area scan per hole, with the survey&apos;s camera, height and overlap, opened in the mission editor</source>
        <translation>Una ruta con un barrido de área por hueco, con la cámara, la altura y el solape del levantamiento, abierta en el editor de misiones</translation>
    </message>
</context>
<context>
    <name>PrivateFiles</name>
    <message>
        <source>Cannot create the folder %1: %2 is not a folder</source>
        <translation>No se puede crear la carpeta %1: %2 no es una carpeta</translation>
    </message>
    <message>
        <source>Cannot create the folder %1: %2</source>
        <translation>No se puede crear la carpeta %1: %2</translation>
    </message>
    <message>
        <source>Cannot create the folder %1</source>
        <translation>No se puede crear la carpeta %1</translation>
    </message>
    <message>
        <source>Cannot create %1: %2</source>
        <translation>No se puede crear %1: %2</translation>
    </message>
    <message>
        <source>Cannot create a private folder in %1: %2</source>
        <translation>No se puede crear una carpeta privada en %1: %2</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source> in %1 s</source>
        <translation> en %1 s</translation>
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
        <translation>no alcanzado</translation>
    </message>
    <message>
        <source>That vehicle is not in this log (it holds %1).</source>
        <translation>Ese vehículo no está en este registro (contiene %1).</translation>
    </message>
    <message>
        <source>no vehicle</source>
        <translation>ningún vehículo</translation>
    </message>
    <message>
        <source>Route &quot;%1&quot; has fewer than two waypoints: there is nothing to compare.</source>
        <translation>La ruta «%1» tiene menos de dos waypoints: no hay nada que comparar.</translation>
    </message>
    <message>
        <source>%1 has no track in this log to compare with.</source>
        <translation>%1 no tiene traza en este registro con la que comparar.</translation>
    </message>
    <message>
        <source>Route &quot;%1&quot; does not match %2: its waypoints are %3 km from anywhere %2 flew in this log.</source>
        <translation>La ruta «%1» no corresponde a %2: sus waypoints están a %3 km de cualquier punto por el que %2 voló en este registro.</translation>
    </message>
    <message>
        <source>%1 flown by %2, %3 to %4
</source>
        <translation>%1 volada por %2, de %3 a %4
</translation>
    </message>
    <message>
        <source>
waypoint  reached                    closest
</source>
        <translation>
waypoint  alcanzado                  más cercano
</translation>
    </message>
    <message>
        <source>
leg      samples  cross-track max  mean      altitude max  mean
</source>
        <translation>
tramo   muestras  desvío lat. máx  media     altitud máx.  media
</translation>
    </message>
    <message>
        <source>
total: %1 reached, %2 missed; cross-track max %3, mean %4; altitude max %5, mean %6
</source>
        <translation>
total: %1 alcanzados, %2 no alcanzados; desvío lateral máx. %3, media %4; altitud máx. %5, media %6
</translation>
    </message>
    <message>
        <source>%1: no such file</source>
        <translation>%1: no existe el archivo</translation>
    </message>
    <message>
        <source>%1: cannot be opened: %2</source>
        <translation>%1: no se puede abrir: %2</translation>
    </message>
    <message>
        <source>no Sortie flight log header</source>
        <translation>sin cabecera de registro de vuelo de Sortie</translation>
    </message>
    <message>
        <source>%1 is not a Sortie flight log (%2)</source>
        <translation>%1 no es un registro de vuelo de Sortie (%2)</translation>
    </message>
    <message>
        <source>%1: the vehicles cannot be read: %2</source>
        <translation>%1: no se pueden leer los vehículos: %2</translation>
    </message>
    <message>
        <source>the vehicle list is damaged: %1</source>
        <translation>la lista de vehículos está dañada: %1</translation>
    </message>
    <message>
        <source>unknown vehicle</source>
        <translation>vehículo desconocido</translation>
    </message>
    <message>
        <source>stopped after %1 good blocks (%2): %3</source>
        <translation>se detuvo tras %1 bloques correctos (%2): %3</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>the telemetry cannot be read: %1</source>
        <translation>no se puede leer la telemetría: %1</translation>
    </message>
    <message>
        <source>the events stop after %1: %2</source>
        <translation>los eventos se interrumpen tras %1: %2</translation>
    </message>
    <message>
        <source>the events cannot be read: %1</source>
        <translation>no se pueden leer los eventos: %1</translation>
    </message>
    <message>
        <source>the routes stop early: %1</source>
        <translation>las rutas se interrumpen antes de tiempo: %1</translation>
    </message>
    <message>
        <source>the routes cannot be read: %1</source>
        <translation>no se pueden leer las rutas: %1</translation>
    </message>
    <message>
        <source>file:     %1
</source>
        <translation>archivo:   %1
</translation>
    </message>
    <message>
        <source>span:     %1 to %2 (%3 s)
</source>
        <translation>periodo:   %1 a %2 (%3 s)
</translation>
    </message>
    <message>
        <source>DAMAGED:  read up to the last good record; %1
</source>
        <translation>DAÑADO:    leído hasta el último registro correcto; %1
</translation>
    </message>
    <message>
        <source>vehicles: %1
</source>
        <translation>vehículos: %1
</translation>
    </message>
    <message>
        <source>, %1 to %2</source>
        <translation>, %1 a %2</translation>
    </message>
    <message>
        <source>    route uploaded %1: %2 waypoints
</source>
        <translation>    ruta subida %1: %2 waypoints
</translation>
    </message>
    <message>
        <source>
events:   %1
</source>
        <translation>
eventos:   %1
</translation>
    </message>
    <message>
        <source> (failed)</source>
        <translation> (fallido)</translation>
    </message>
    <message>
        <source>a replayed vehicle takes no commands</source>
        <translation>un vehículo reproducido no acepta órdenes</translation>
    </message>
    <message>
        <source>block %1 (vehicle row %2, from %3) is skipped: %4</source>
        <translation>el bloque %1 (fila de vehículo %2, desde %3) se omite: %4</translation>
    </message>
    <message numerus="yes">
        <source>%n more damaged block(s) skipped</source>
        <translation>
            <numerusform>%n bloque dañado más omitido</numerusform>
            <numerusform>%n bloques dañados más omitidos</numerusform>
        </translation>
    </message>
    <message>
        <source>read up to the last good record: %1</source>
        <translation>leído hasta el último registro válido: %1</translation>
    </message>
    <message>
        <source>DAMAGED:  %1
</source>
        <translation>DAÑADO:  %1
</translation>
    </message>
    <message>
        <source>%1: cannot be opened: no private copy to recover it in (%2)</source>
        <translation>%1: no se puede abrir: no hay copia privada en la que recuperarlo (%2)</translation>
    </message>
    <message>
        <source>%1 is not a Sortie flight log (its %2 is a %3, not a table)</source>
        <translation>%1 no es un registro de vuelo de Sortie (su %2 es un %3, no una tabla)</translation>
    </message>
    <message>
        <source>stopped: %1</source>
        <translation>detenido: %1</translation>
    </message>
</context>
<context>
    <name>QgcFenceJson</name>
    <message>
        <source>expected [latitude, longitude]</source>
        <translation>se esperaba [latitud, longitud]</translation>
    </message>
    <message>
        <source>latitude or longitude out of range</source>
        <translation>latitud o longitud fuera de rango</translation>
    </message>
    <message>
        <source>expected [latitude, longitude, altitude]</source>
        <translation>se esperaba [latitud, longitud, altitud]</translation>
    </message>
    <message>
        <source>a polygon needs at least 3 vertices, found %1</source>
        <translation>un polígono necesita al menos 3 vértices, se encontraron %1</translation>
    </message>
    <message>
        <source>Geofence polygon at %1 was left out: %2</source>
        <translation>Se omitió el polígono de geocerca en %1: %2</translation>
    </message>
    <message>
        <source>the radius must be positive metres</source>
        <translation>el radio debe ser un número positivo de metros</translation>
    </message>
    <message>
        <source>The geofence&apos;s breach return point at %1 was left out: %2</source>
        <translation>Se omitió el punto de retorno por violación de la geocerca en %1: %2</translation>
    </message>
    <message>
        <source>The geofence polygons at %1 were left out: %2</source>
        <translation>Se omitieron los polígonos de geovalla en %1: %2</translation>
    </message>
    <message>
        <source>Geofence circle at %1 was left out: %2</source>
        <translation>Se omitió el círculo de geovalla en %1: %2</translation>
    </message>
    <message>
        <source>The geofence circles at %1 were left out: %2</source>
        <translation>Se omitieron los círculos de geovalla en %1: %2</translation>
    </message>
    <message>
        <source>Rally point at %1 was left out: %2</source>
        <translation>Se omitió el punto de reunión en %1: %2</translation>
    </message>
    <message>
        <source>The rally points at %1 were left out: %2</source>
        <translation>Se omitieron los puntos de reunión en %1: %2</translation>
    </message>
</context>
<context>
    <name>QgcPlanFormat</name>
    <message>
        <source>expected 7 params (or 4 and a &quot;coordinate&quot;), found %1</source>
        <translation>se esperaban 7 params (o 4 y una «coordinate»), se encontraron %1</translation>
    </message>
    <message>
        <source>not a QGroundControl plan (fileType is not &quot;Plan&quot;)</source>
        <translation>no es un plan de QGroundControl (fileType no es «Plan»)</translation>
    </message>
    <message>
        <source>plan version %1 is not supported (Sortie reads version 1)</source>
        <translation>la versión de plan %1 no es compatible (Sortie lee la versión 1)</translation>
    </message>
    <message>
        <source>mission version %1 is not supported (Sortie reads version 2)</source>
        <translation>la versión de misión %1 no es compatible (Sortie lee la versión 2)</translation>
    </message>
    <message>
        <source>the planned home position is out of range</source>
        <translation>la posición de origen planificada está fuera de rango</translation>
    </message>
    <message>
        <source>complex item &quot;%1&quot; is not supported; Sortie imports surveys, corridor and structure scans</source>
        <translation>el elemento complejo «%1» no es compatible; Sortie importa levantamientos y escaneos de corredor y de estructura</translation>
    </message>
    <message>
        <source>unknown item type &quot;%1&quot;</source>
        <translation>tipo de elemento desconocido «%1»</translation>
    </message>
    <message>
        <source>A corridor was left out: %1</source>
        <translation>Se omitió un corredor: %1</translation>
    </message>
    <message>
        <source>An area scan was left out: %1</source>
        <translation>Se omitió un escaneo de área: %1</translation>
    </message>
    <message>
        <source>The route has no home position: the first point was written as home, at 0 m AMSL.</source>
        <translation>La ruta no tiene posición de origen: el primer punto se escribió como origen, a 0 m AMSL.</translation>
    </message>
</context>
<context>
    <name>QgcSurveyJson</name>
    <message>
        <source>latitude/longitude out of range</source>
        <translation>latitud/longitud fuera de rango</translation>
    </message>
    <message>
        <source>a survey polygon needs at least 3 vertices, found %1</source>
        <translation>un polígono de levantamiento necesita al menos 3 vértices, se encontraron %1</translation>
    </message>
    <message>
        <source>Custom Camera</source>
        <translation>Custom Camera</translation>
    </message>
    <message>
        <source>the survey&apos;s camera has neither a sensor nor footprints</source>
        <translation>la cámara del levantamiento no tiene ni sensor ni huellas</translation>
    </message>
    <message>
        <source>%1: the survey&apos;s manual camera was replaced by one with the same footprints</source>
        <translation>%1: la cámara manual del levantamiento se sustituyó por una con las mismas huellas</translation>
    </message>
    <message>
        <source>a %1 needs at least %2 points, found %3</source>
        <translation>%1: se necesitan al menos %2 puntos, se encontraron %3</translation>
    </message>
    <message>
        <source>%1: the camera &quot;%2&quot; is not one Sortie knows; it is kept by name, and the server must know it.</source>
        <translation>%1: Sortie no conoce la cámara «%2»; se conserva por su nombre y el servidor debe conocerla.</translation>
    </message>
    <message>
        <source>the corridor&apos;s camera has no sensor to turn its distance into a ground sample distance</source>
        <translation>la cámara del corredor no tiene sensor con el que convertir su distancia en una distancia de muestreo (GSD)</translation>
    </message>
    <message>
        <source>corridor centre line</source>
        <translation>línea central del corredor</translation>
    </message>
    <message>
        <source>structure polygon</source>
        <translation>polígono de la estructura</translation>
    </message>
    <message>
        <source>%1: the structure scan became a perimeter flight at %2 m%3.</source>
        <translation>%1: el escaneo de estructura pasó a ser un vuelo perimetral a %2 m%3.</translation>
    </message>
    <message>
        <source>, its %1 layers as %1 loops at one height</source>
        <translation>, sus %1 capas como %1 vueltas a una sola altura</translation>
    </message>
</context>
<context>
    <name>RasterFootprint</name>
    <message>
        <source>the raster&apos;s geotransform cannot be inverted (a zero pixel size?)</source>
        <translation>la geotransformación del ráster no se puede invertir (¿tamaño de píxel cero?)</translation>
    </message>
    <message>
        <source>the raster has no pixels (%1×%2)</source>
        <translation>el ráster no tiene píxeles (%1×%2)</translation>
    </message>
    <message>
        <source>the raster&apos;s geotransform is not finite</source>
        <translation>la geotransformación del ráster no es finita</translation>
    </message>
</context>
<context>
    <name>RemoveSegmentsCommand</name>
    <message>
        <source>Delete %1</source>
        <translation>Eliminar %1</translation>
    </message>
    <message>
        <source>Delete %1 rows</source>
        <translation>Eliminar %1 filas</translation>
    </message>
</context>
<context>
    <name>ReorderSegmentsCommand</name>
    <message>
        <source>Move row %1</source>
        <translation>Mover la fila %1</translation>
    </message>
    <message>
        <source>Move %1 rows</source>
        <translation>Mover %1 filas</translation>
    </message>
    <message>
        <source>Reverse rows %1-%2</source>
        <translation>Invertir las filas %1-%2</translation>
    </message>
</context>
<context>
    <name>ReplayTimeline</name>
    <message>
        <source>Open a flight log</source>
        <translation>Abrir un registro de vuelo</translation>
    </message>
    <message>
        <source>Flight logs (*.sortielog)</source>
        <translation>Registros de vuelo (*.sortielog)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Export tracks</source>
        <translation>Exportar trazas</translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation>Exportado a %1.</translation>
    </message>
    <message>
        <source>Open log…</source>
        <translation>Abrir registro…</translation>
    </message>
    <message>
        <source>Server history…</source>
        <translation>Historial del servidor…</translation>
    </message>
    <message>
        <source>REPLAY — %1</source>
        <translation>REPRODUCCIÓN — %1</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Reproducir</translation>
    </message>
    <message>
        <source>Previous event</source>
        <translation>Evento anterior</translation>
    </message>
    <message>
        <source>Next event</source>
        <translation>Evento siguiente</translation>
    </message>
    <message>
        <source>Jump to event (%1)</source>
        <translation>Saltar al evento (%1)</translation>
    </message>
    <message>
        <source>Loading plots…</source>
        <translation>Cargando gráficas…</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportar…</translation>
    </message>
    <message>
        <source>Back to live</source>
        <translation>Volver a en vivo</translation>
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
        <translation>Ediciones guardadas automáticamente</translation>
    </message>
    <message>
        <source>Restore one of %1 unsaved routes?</source>
        <translation>¿Restaurar una de las %1 rutas sin guardar?</translation>
    </message>
    <message>
        <source>Restore unsaved edits?</source>
        <translation>¿Restaurar las ediciones sin guardar?</translation>
    </message>
    <message>
        <source>Sortie did not close normally. These routes had unsaved edits, saved automatically. Choose one to see its changes; the others are kept and offered again at the next start.</source>
        <translation>Sortie no se cerró correctamente. Estas rutas tenían ediciones sin guardar, que se guardaron automáticamente. Elija una para ver sus cambios; las demás se conservan y se ofrecen de nuevo en el próximo inicio.</translation>
    </message>
    <message>
        <source>Sortie did not close normally. Edits of “%1” were saved automatically at %2.</source>
        <translation>Sortie no se cerró correctamente. Las ediciones de «%1» se guardaron automáticamente a las %2.</translation>
    </message>
    <message>
        <source>%1 — saved %2</source>
        <translation>%1 — guardado %2</translation>
    </message>
    <message>
        <source>It belongs to %1.</source>
        <translation>Pertenece a %1.</translation>
    </message>
    <message>
        <source>Changes since the last save:</source>
        <translation>Cambios desde el último guardado:</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>Aceptar</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Descartar</translation>
    </message>
    <message>
        <source>Start without these edits (the file is kept as a backup)</source>
        <translation>Iniciar sin estas ediciones (el archivo se conserva como copia de seguridad)</translation>
    </message>
    <message>
        <source>Later</source>
        <translation>Más tarde</translation>
    </message>
    <message>
        <source>Keep them and decide after signing in</source>
        <translation>Conservarlas y decidir después de iniciar sesión</translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Restaurar</translation>
    </message>
</context>
<context>
    <name>ResumePanel</name>
    <message>
        <source>Resume from the last photo</source>
        <translation>Reanudar desde la última foto</translation>
    </message>
    <message>
        <source>Resume from the last waypoint</source>
        <translation>Reanudar desde el último punto de ruta</translation>
    </message>
</context>
<context>
    <name>ResumeRoute</name>
    <message>
        <source>%1 cannot be resumed here: %2</source>
        <translation>%1 no se puede reanudar aquí: %2</translation>
    </message>
    <message>
        <source>the take-off point is not known</source>
        <translation>no se conoce el punto de despegue</translation>
    </message>
    <message>
        <source>the route has nothing to fly</source>
        <translation>la ruta no tiene nada que volar</translation>
    </message>
    <message>
        <source>none of the waypoints the vehicle reached is on this route&apos;s path: not this route&apos;s flight</source>
        <translation>ninguno de los puntos que alcanzó el vehículo está en la trayectoria de esta ruta: no es un vuelo de esta ruta</translation>
    </message>
    <message>
        <source>The last waypoint the vehicle reached is not one of the route&apos;s own: the rest starts at the route&apos;s point before it.</source>
        <translation>El último punto que alcanzó el vehículo no es de la ruta: el resto empieza en el punto de la ruta anterior.</translation>
    </message>
    <message>
        <source>where the last photo was taken is not known</source>
        <translation>no se sabe dónde se tomó la última foto</translation>
    </message>
    <message>
        <source>the last photo was taken %1 m from the route&apos;s path, more than the %2 m a flight of it strays: not this route&apos;s flight</source>
        <translation>la última foto se tomó a %1 m de la trayectoria de la ruta, más de los %2 m que se desvía un vuelo: no es un vuelo de esta ruta</translation>
    </message>
    <message>
        <source>The photos were taken every %1 s: the next one is taken as due %2 m on at the leg&apos;s speed.</source>
        <translation>Las fotos se tomaban cada %1 s: la siguiente se considera debida %2 m más adelante a la velocidad del tramo.</translation>
    </message>
    <message>
        <source>No photo series was running at the last photo: the rest starts where it was taken.</source>
        <translation>No había ninguna serie de fotos en curso en la última foto: el resto empieza donde se tomó.</translation>
    </message>
    <message>
        <source>the last photo was the route&apos;s last: nothing is left to fly</source>
        <translation>la última foto fue la última de la ruta: no queda nada que volar</translation>
    </message>
    <message>
        <source>the route was flown to its last point: nothing is left to fly</source>
        <translation>la ruta se voló hasta su último punto: no queda nada que volar</translation>
    </message>
    <message>
        <source>%1 (resumed)</source>
        <translation>%1 (reanudada)</translation>
    </message>
    <message>
        <source>Route</source>
        <translation>Ruta</translation>
    </message>
    <message>
        <source>Resumes %1, %2 m into the flight (%3 m left), after a take-off and a flight over at %4 m.</source>
        <translation>Reanuda %1, a %2 m del inicio del vuelo (quedan %3 m), tras un despegue y un vuelo de aproximación a %4 m.</translation>
    </message>
    <message>
        <source>The photo series every %1 m starts again at the resume point.</source>
        <translation>La serie de fotos cada %1 m empieza de nuevo en el punto de reanudación.</translation>
    </message>
    <message>
        <source>The photo series every %1 s starts again at the resume point.</source>
        <translation>La serie de fotos cada %1 s empieza de nuevo en el punto de reanudación.</translation>
    </message>
    <message>
        <source>The gimbal is tilted to %1° there, as it was.</source>
        <translation>El gimbal se inclina allí a %1°, como estaba.</translation>
    </message>
    <message>
        <source>the place to resume from is not on the route&apos;s path</source>
        <translation>el lugar desde el que reanudar no está en la trayectoria de la ruta</translation>
    </message>
    <message>
        <source>the place to resume from is %1 m from where the route&apos;s path is that far along</source>
        <translation>el lugar desde el que reanudar está a %1 m de donde la trayectoria de la ruta llega a esa distancia</translation>
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
        <translation>Escaneo %1</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(ninguno)</translation>
    </message>
    <message>
        <source>return home</source>
        <translation>volver al origen</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>No changes</source>
        <translation>Sin cambios</translation>
    </message>
    <message>
        <source>1 change: </source>
        <translation>1 cambio: </translation>
    </message>
    <message>
        <source>%1 changes: </source>
        <translation>%1 cambios: </translation>
    </message>
    <message>
        <source> and %1 more</source>
        <translation> y %1 más</translation>
    </message>
    <message>
        <source>name %1 → %2</source>
        <translation>nombre %1 → %2</translation>
    </message>
    <message>
        <source>%1 %2 → %3 %4</source>
        <translation>%1 %2 → %3 %4</translation>
    </message>
    <message>
        <source>safe altitude</source>
        <translation>altitud de seguridad</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>maximum altitude</source>
        <translation>altitud máxima</translation>
    </message>
    <message>
        <source>initial speed</source>
        <translation>velocidad inicial</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>maximum speed</source>
        <translation>velocidad máxima</translation>
    </message>
    <message>
        <source>corner radius</source>
        <translation>radio de esquina</translation>
    </message>
    <message>
        <source>takeoff height</source>
        <translation>altura de despegue</translation>
    </message>
    <message>
        <source>vehicle profile %1 → %2</source>
        <translation>perfil de vehículo %1 → %2</translation>
    </message>
    <message>
        <source>vehicle profile %1 changed</source>
        <translation>perfil de vehículo %1 modificado</translation>
    </message>
    <message>
        <source>failsafe actions changed</source>
        <translation>acciones de failsafe modificadas</translation>
    </message>
    <message>
        <source>home set</source>
        <translation>origen fijado</translation>
    </message>
    <message>
        <source>home removed</source>
        <translation>origen eliminado</translation>
    </message>
    <message>
        <source>home moved %1 m</source>
        <translation>origen desplazado %1 m</translation>
    </message>
    <message>
        <source>home altitude %1 → %2 m</source>
        <translation>altitud del origen %1 → %2 m</translation>
    </message>
    <message>
        <source>end action %1 → %2</source>
        <translation>acción final %1 → %2</translation>
    </message>
    <message>
        <source>on</source>
        <translation>activada</translation>
    </message>
    <message>
        <source>off</source>
        <translation>desactivada</translation>
    </message>
    <message>
        <source>aerodrome zone check</source>
        <translation>comprobación de zonas de aeródromo</translation>
    </message>
    <message>
        <source>custom zone check</source>
        <translation>comprobación de zonas personalizadas</translation>
    </message>
    <message>
        <source>%1 removed</source>
        <translation>%1 eliminado</translation>
    </message>
    <message>
        <source>%1 added</source>
        <translation>%1 añadido</translation>
    </message>
    <message>
        <source>%1 changed</source>
        <translation>%1 modificado</translation>
    </message>
    <message>
        <source>%1 moved %2 m</source>
        <translation>%1 desplazado %2 m</translation>
    </message>
    <message>
        <source>altitude of %1 %2 m %3 → %4 m %5</source>
        <translation>altitud de %1: %2 m %3 → %4 m %5</translation>
    </message>
    <message>
        <source>altitude of %1 %2 → %3 m</source>
        <translation>altitud de %1: %2 → %3 m</translation>
    </message>
    <message>
        <source>speed of %1 %2 → %3 m/s</source>
        <translation>velocidad de %1: %2 → %3 m/s</translation>
    </message>
    <message>
        <source>actions of %1: %2 → %3</source>
        <translation>acciones de %1: %2 → %3</translation>
    </message>
    <message>
        <source>turn at %1 %2 → %3</source>
        <translation>giro en %1: %2 → %3</translation>
    </message>
    <message>
        <source>acceptance radius of %1 %2 → %3 m</source>
        <translation>radio de aceptación de %1: %2 → %3 m</translation>
    </message>
    <message>
        <source>%1 %2 → %3</source>
        <translation>%1 %2 → %3</translation>
    </message>
    <message>
        <source>figure of %1 reshaped</source>
        <translation>figura de %1 modificada</translation>
    </message>
    <message>
        <source>%1 of %2 %3 → %4</source>
        <translation>%1 de %2: %3 → %4</translation>
    </message>
    <message>
        <source>%1 of %2 removed</source>
        <translation>%1 de %2 eliminado</translation>
    </message>
    <message>
        <source>actions of %1 changed</source>
        <translation>acciones de %1 modificadas</translation>
    </message>
    <message>
        <source>area of %1 reshaped</source>
        <translation>área de %1 modificada</translation>
    </message>
    <message>
        <source>area of %1 reshaped (%2 → %3 corners)</source>
        <translation>área de %1 modificada (%2 → %3 esquinas)</translation>
    </message>
    <message>
        <source>%1 of %2 %3 → %4 %5</source>
        <translation>%1 de %2: %3 → %4 %5</translation>
    </message>
    <message>
        <source>altitude</source>
        <translation>altitud</translation>
    </message>
    <message>
        <source>altitude of %1 now %2</source>
        <translation>altitud de %1 ahora %2</translation>
    </message>
    <message>
        <source>%1 now flies by ground sample distance</source>
        <translation>%1 vuela ahora por distancia de muestreo (GSD)</translation>
    </message>
    <message>
        <source>%1 now flies by altitude</source>
        <translation>%1 vuela ahora por altitud</translation>
    </message>
    <message>
        <source>front overlap</source>
        <translation>solape frontal</translation>
    </message>
    <message>
        <source>side overlap</source>
        <translation>solape lateral</translation>
    </message>
    <message>
        <source>direction</source>
        <translation>dirección</translation>
    </message>
    <message>
        <source>turnaround</source>
        <translation>viraje</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>velocidad</translation>
    </message>
    <message>
        <source>camera of %1 %2 → %3</source>
        <translation>cámara de %1 %2 → %3</translation>
    </message>
    <message>
        <source>camera of %1 changed</source>
        <translation>cámara de %1 modificada</translation>
    </message>
    <message>
        <source>planned start %1</source>
        <translation>inicio previsto %1</translation>
    </message>
    <message>
        <source>planned start removed: now</source>
        <translation>inicio previsto quitado: ahora</translation>
    </message>
    <message>
        <source>authorisation for %1: %2</source>
        <translation>autorización para %1: %2</translation>
    </message>
    <message>
        <source>authorisation for %1 removed</source>
        <translation>autorización para %1 quitada</translation>
    </message>
</context>
<context>
    <name>RouteEndurance</name>
    <message>
        <source>No energy profile: choose the vehicle&apos;s profile file</source>
        <translation>Sin perfil energético: elija el archivo de perfil del vehículo</translation>
    </message>
    <message>
        <source>The route has no points</source>
        <translation>La ruta no tiene ningún punto</translation>
    </message>
</context>
<context>
    <name>RoutePanel</name>
    <message>
        <source>Import a route</source>
        <translation>Importar una ruta</translation>
    </message>
    <message>
        <source>Routes (*.sortie *.plan *.waypoints *.txt *.kml *.kmz)</source>
        <translation>Rutas (*.sortie *.plan *.waypoints *.txt *.kml *.kmz)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Todos los archivos (*)</translation>
    </message>
    <message>
        <source>The vehicle&apos;s energy profile</source>
        <translation>Perfil energético del vehículo</translation>
    </message>
    <message>
        <source>Energy profiles (*.json)</source>
        <translation>Perfiles energéticos (*.json)</translation>
    </message>
    <message>
        <source>Export the route</source>
        <translation>Exportar la ruta</translation>
    </message>
    <message>
        <source>Sortie (*.sortie)</source>
        <translation>Sortie (*.sortie)</translation>
    </message>
    <message>
        <source>QGroundControl plan (*.plan)</source>
        <translation>Plan de QGroundControl (*.plan)</translation>
    </message>
    <message>
        <source>Waypoint list (*.waypoints)</source>
        <translation>Lista de waypoints (*.waypoints)</translation>
    </message>
    <message>
        <source>KML (*.kml)</source>
        <translation>KML (*.kml)</translation>
    </message>
    <message>
        <source>DJI Pilot 2 route, WPML (*.kmz)</source>
        <translation>Ruta de DJI Pilot 2, WPML (*.kmz)</translation>
    </message>
    <message>
        <source>Choose a route…</source>
        <translation>Elegir una ruta…</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Abrir</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Guardar</translation>
    </message>
    <message>
        <source>Save on the server, under its lock (Ctrl+S)</source>
        <translation>Guardar en el servidor, bajo su bloqueo (Ctrl+S)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Deshacer</translation>
    </message>
    <message>
        <source>Undo %1 (Ctrl+Z)</source>
        <translation>Deshacer %1 (Ctrl+Z)</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Rehacer</translation>
    </message>
    <message>
        <source>Redo %1 (Ctrl+Shift+Z)</source>
        <translation>Rehacer %1 (Ctrl+Mayús+Z)</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Eliminar</translation>
    </message>
    <message>
        <source>Delete the selected waypoints (Del)</source>
        <translation>Eliminar los waypoints seleccionados (Supr)</translation>
    </message>
    <message>
        <source>Area scan</source>
        <translation>Escaneo de área</translation>
    </message>
    <message>
        <source>Draw an area to scan: click its corners on the map</source>
        <translation>Dibuje un área que escanear: haga clic en sus esquinas en el mapa</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>Importar…</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportar…</translation>
    </message>
    <message>
        <source>Zone checks…</source>
        <translation>Comprobación de zonas…</translation>
    </message>
    <message>
        <source>Which no-fly zones the server&apos;s processing refuses the route for</source>
        <translation>Por qué zonas de no vuelo rechaza la ruta el procesamiento del servidor</translation>
    </message>
    <message>
        <source>Refuse crossing aerodrome zones</source>
        <translation>Rechazar si cruza zonas de aeródromo</translation>
    </message>
    <message>
        <source>Refuse crossing custom zones</source>
        <translation>Rechazar si cruza zonas personalizadas</translation>
    </message>
    <message>
        <source>Process</source>
        <translation>Procesar</translation>
    </message>
    <message>
        <source>Prepare the route for the chosen vehicle, as the upload will, and show what it would fly (Ctrl+P)</source>
        <translation>Preparar la ruta para el vehículo elegido, como lo hará la subida, y mostrar lo que volaría (Ctrl+P)</translation>
    </message>
    <message>
        <source>Vehicle…</source>
        <translation>Vehículo…</translation>
    </message>
    <message>
        <source>Upload</source>
        <translation>Subir</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Yours (version %1, edited) against theirs (version %2, grey on the map):</source>
        <translation>La suya (versión %1, editada) frente a la otra (versión %2, en gris en el mapa):</translation>
    </message>
    <message>
        <source>They changed: %1</source>
        <translation>Cambiaron: %1</translation>
    </message>
    <message>
        <source>Keep mine (overwrite theirs)</source>
        <translation>Conservar la mía (sobrescribir la otra)</translation>
    </message>
    <message>
        <source>Take theirs (undo brings mine back)</source>
        <translation>Tomar la otra (Deshacer recupera la mía)</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Longitud</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Tiempo</translation>
    </message>
    <message>
        <source>Waypoints</source>
        <translation>Waypoints</translation>
    </message>
    <message>
        <source>Photos</source>
        <translation>Fotos</translation>
    </message>
    <message>
        <source>Conflicts with other vehicles</source>
        <translation>Conflictos con otros vehículos</translation>
    </message>
    <message>
        <source>%1:%2  leg %3 · %4 (%5): %6 m across, %7 m in height</source>
        <translation>%1:%2  tramo %3 · %4 (%5): %6 m en horizontal, %7 m en altura</translation>
    </message>
    <message>
        <source>flying</source>
        <translation>en vuelo</translation>
    </message>
    <message>
        <source>uploaded</source>
        <translation>subida</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Energía</translation>
    </message>
    <message>
        <source>%1 Wh</source>
        <translation>%1 Wh</translation>
    </message>
    <message numerus="yes">
        <source>%n batteries</source>
        <translation>
            <numerusform>%n batería</numerusform>
            <numerusform>%n baterías</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 % left</source>
        <translation>%1 % restante</translation>
    </message>
    <message>
        <source>No return</source>
        <translation>Sin retorno</translation>
    </message>
    <message>
        <source>unknown: no home</source>
        <translation>desconocido: sin origen</translation>
    </message>
    <message>
        <source>after %1 (leg %2)</source>
        <translation>tras %1 (tramo %2)</translation>
    </message>
    <message>
        <source>none: home in reach</source>
        <translation>ninguno: origen al alcance</translation>
    </message>
    <message>
        <source>Beyond this point of the route, flying straight home no longer lands with the reserve</source>
        <translation>Pasado este punto de la ruta, volar en línea recta al origen ya no permite aterrizar con la reserva</translation>
    </message>
    <message>
        <source>Load an energy profile to see whether the battery lasts.</source>
        <translation>Cargue un perfil energético para ver si la batería alcanza.</translation>
    </message>
    <message>
        <source>Profile</source>
        <translation>Perfil</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>unnamed</source>
        <translation>sin nombre</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Cargar…</translation>
    </message>
    <message>
        <source>The vehicle&apos;s energy profile: a JSON file, e.g. from sortie-log fit</source>
        <translation>Perfil energético del vehículo: un archivo JSON, p. ej. de sortie-log fit</translation>
    </message>
    <message>
        <source>Wind</source>
        <translation>Viento</translation>
    </message>
    <message>
        <source>Wind speed, m/s</source>
        <translation>Velocidad del viento, m/s</translation>
    </message>
    <message>
        <source>m/s from</source>
        <translation>m/s desde</translation>
    </message>
    <message>
        <source>The direction the wind blows from, degrees clockwise from north</source>
        <translation>Dirección desde la que sopla el viento, en grados en sentido horario desde el norte</translation>
    </message>
    <message>
        <source>Select the segment</source>
        <translation>Seleccionar el segmento</translation>
    </message>
    <message>
        <source>Planned start</source>
        <translation>Inicio previsto</translation>
    </message>
    <message>
        <source>now (or e.g. %1)</source>
        <translation>ahora (o p. ej. %1)</translation>
    </message>
    <message>
        <source>Year-month-day hours:minutes, your time zone; empty: the flight starts now</source>
        <translation>Año-mes-día horas:minutos, su zona horaria; vacío: el vuelo empieza ahora</translation>
    </message>
</context>
<context>
    <name>RouteValidator</name>
    <message>
        <source>%1: the position is not valid.</source>
        <translation>%1: la posición no es válida.</translation>
    </message>
    <message>
        <source>The route needs at least two points; it has %1.</source>
        <translation>La ruta necesita al menos dos puntos; tiene %1.</translation>
    </message>
    <message numerus="yes">
        <source>%n AMSL altitude(s), the first at %1, were not checked against the route&apos;s limits: the take-off elevation is unknown.</source>
        <translation>
            <numerusform>%n altitud AMSL (en %1) no se comprobó con los límites de la ruta: se desconoce la elevación del despegue.</numerusform>
            <numerusform>%n altitudes AMSL, la primera en %1, no se comprobaron con los límites de la ruta: se desconoce la elevación del despegue.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: altitude %2 is below the route&apos;s safe altitude of %3 m.</source>
        <translation>%1: la altitud %2 está por debajo de la altitud de seguridad de la ruta de %3 m.</translation>
    </message>
    <message>
        <source>%1: the speed must be positive.</source>
        <translation>%1: la velocidad debe ser positiva.</translation>
    </message>
    <message>
        <source>%1: speed %2 m/s is above the vehicle&apos;s limit of %3 m/s.</source>
        <translation>%1: la velocidad %2 m/s supera el límite del vehículo de %3 m/s.</translation>
    </message>
    <message>
        <source>%1: Sortie does not know the algorithm %2; the server checks it when it processes the route.</source>
        <translation>%1: Sortie no conoce el algoritmo %2; el servidor lo comprueba al procesar la ruta.</translation>
    </message>
    <message>
        <source>%1 repeats %2.</source>
        <translation>%1 repite %2.</translation>
    </message>
    <message>
        <source>%1 is %2 but %3 is %4: the climb between them is not estimated.</source>
        <translation>%1 es %2 pero %3 es %4: no se estima el ascenso entre ellos.</translation>
    </message>
    <message>
        <source>The route</source>
        <translation>La ruta</translation>
    </message>
    <message>
        <source>%1: %2 m above the take-off point (altitude %3); the route&apos;s limit is %4 m above it.</source>
        <translation>%1: %2 m sobre el punto de despegue (altitud %3); el límite de la ruta es %4 m sobre él.</translation>
    </message>
</context>
<context>
    <name>SbsFeed</name>
    <message>
        <source>line %1: %2</source>
        <translation>línea %1: %2</translation>
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
        <translation>La vista 3D necesita OpenGL: inicie Sortie con QSG_RHI_BACKEND=opengl.</translation>
    </message>
    <message>
        <source>Open a route to see it in 3D.</source>
        <translation>Abra una ruta para verla en 3D.</translation>
    </message>
    <message>
        <source>Purple ground: no elevation data there.</source>
        <translation>Terreno morado: sin datos de elevación.</translation>
    </message>
    <message>
        <source>Vertical exaggeration</source>
        <translation>Exageración vertical</translation>
    </message>
    <message>
        <source>Fit route</source>
        <translation>Encuadrar ruta</translation>
    </message>
</context>
<context>
    <name>SegmentEditor</name>
    <message>
        <source>Radius</source>
        <translation>Radio</translation>
    </message>
    <message>
        <source>Advanced parameters</source>
        <translation>Parámetros avanzados</translation>
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
        <translation>Radio de aceptación</translation>
    </message>
    <message>
        <source>Sensor width (mm)</source>
        <translation>Ancho del sensor (mm)</translation>
    </message>
    <message>
        <source>Sensor height (mm)</source>
        <translation>Alto del sensor (mm)</translation>
    </message>
    <message>
        <source>Focal length (mm)</source>
        <translation>Distancia focal (mm)</translation>
    </message>
    <message>
        <source>Image width (px)</source>
        <translation>Ancho de imagen (px)</translation>
    </message>
    <message>
        <source>Image height (px)</source>
        <translation>Alto de imagen (px)</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Altura</translation>
    </message>
    <message>
        <source>Side distance (0: from the camera)</source>
        <translation>Distancia lateral (0: según la cámara)</translation>
    </message>
</context>
<context>
    <name>SegmentParameters</name>
    <message>
        <source>%1 needs a number, not &quot;%2&quot;.</source>
        <translation>%1 necesita un número, no «%2».</translation>
    </message>
    <message>
        <source>altitudeType is AGL or AMSL, not &quot;%1&quot;.</source>
        <translation>altitudeType es AGL o AMSL, no «%1».</translation>
    </message>
    <message>
        <source>camera needs a name.</source>
        <translation>camera necesita un nombre.</translation>
    </message>
    <message>
        <source>An area scan has no parameter &quot;%1&quot;.</source>
        <translation>Un escaneo de área no tiene ningún parámetro «%1».</translation>
    </message>
    <message>
        <source>wpTurnType is STOP_AND_TURN, STRAIGHT, SPLINE or BANK_TURN, not &quot;%1&quot;.</source>
        <translation>wpTurnType es STOP_AND_TURN, STRAIGHT, SPLINE o BANK_TURN, no «%1».</translation>
    </message>
    <message>
        <source>A waypoint has no parameter &quot;%1&quot;.</source>
        <translation>Un waypoint no tiene ningún parámetro «%1».</translation>
    </message>
    <message>
        <source>%1 has no parameter &quot;%2&quot;.</source>
        <translation>%1 no tiene ningún parámetro «%2».</translation>
    </message>
    <message>
        <source>%1 cannot take that value.</source>
        <translation>%1 no admite ese valor.</translation>
    </message>
    <message>
        <source>%1 is true or false, not &quot;%2&quot;.</source>
        <translation>%1 es true o false, no «%2».</translation>
    </message>
    <message>
        <source>%1 must be from %2 to below %3.</source>
        <translation>%1 debe estar entre %2 y menos de %3.</translation>
    </message>
    <message>
        <source>%1 must be from %2 to %3.</source>
        <translation>%1 debe estar entre %2 y %3.</translation>
    </message>
</context>
<context>
    <name>SegmentPlanner</name>
    <message>
        <source>The segment has no point</source>
        <translation>El segmento no tiene ningún punto</translation>
    </message>
    <message>
        <source>Point 1 is not a position on the globe</source>
        <translation>El punto 1 no es una posición del globo</translation>
    </message>
    <message>
        <source>The circle has no centre point</source>
        <translation>El círculo no tiene punto central</translation>
    </message>
    <message>
        <source>The circle&apos;s centre is not a position on the globe</source>
        <translation>El centro del círculo no es una posición del globo</translation>
    </message>
    <message>
        <source>The circle needs a positive radius (metres, the figure&apos;s first parameter)</source>
        <translation>El círculo necesita un radio positivo (en metros, el primer parámetro de la figura)</translation>
    </message>
    <message>
        <source>The circle&apos;s radius of %1 m is over the %2 m a segment may span</source>
        <translation>El radio del círculo, de %1 m, supera los %2 m que puede abarcar un segmento</translation>
    </message>
    <message>
        <source>loops: %1 laps of %2 points are too many</source>
        <translation>loops: %1 vueltas de %2 puntos son demasiadas</translation>
    </message>
    <message numerus="yes">
        <source>Orbit of %1 m radius: %n lap(s) of %2 points, %3</source>
        <translation>
            <numerusform>Órbita de %1 m de radio: %n vuelta de %2 puntos, %3</numerusform>
            <numerusform>Órbita de %1 m de radio: %n vueltas de %2 puntos, %3</numerusform>
        </translation>
    </message>
    <message>
        <source>clockwise</source>
        <translation>en sentido horario</translation>
    </message>
    <message>
        <source>counter-clockwise</source>
        <translation>en sentido antihorario</translation>
    </message>
    <message>
        <source>Point %1 is not a position on the globe (latitude and longitude in range)</source>
        <translation>El punto %1 no es una posición del globo (latitud y longitud dentro de rango)</translation>
    </message>
    <message>
        <source>speed: the segment needs a positive speed</source>
        <translation>speed: el segmento necesita una velocidad positiva</translation>
    </message>
    <message>
        <source>No planner knows the algorithm &apos;%1&apos;</source>
        <translation>Ningún planificador conoce el algoritmo «%1»</translation>
    </message>
</context>
<context>
    <name>SegmentWaypoints</name>
    <message>
        <source>cannot be planned</source>
        <translation>no se puede planificar</translation>
    </message>
    <message>
        <source>only a UgCS server that knows %1 can plan it</source>
        <translation>solo un servidor UgCS que conozca %1 puede planificarlo</translation>
    </message>
    <message>
        <source>no such segment</source>
        <translation>no existe ese segmento</translation>
    </message>
</context>
<context>
    <name>ServerAction</name>
    <message>
        <source>Server action</source>
        <translation>Acción del servidor</translation>
    </message>
</context>
<context>
    <name>ServerAddress</name>
    <message>
        <source>the server address is empty (expected host:port)</source>
        <translation>la dirección del servidor está vacía (se esperaba host:puerto)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; opens an IPv6 address with [ but never closes it</source>
        <translation>«%1» abre una dirección IPv6 con [ pero nunca la cierra</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has text after the IPv6 address that is not :port</source>
        <translation>«%1» tiene texto tras la dirección IPv6 que no es :puerto</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an IPv6 address</source>
        <translation>«%1» no es una dirección IPv6</translation>
    </message>
    <message>
        <source>write an IPv6 server address in brackets: [%1]:3334</source>
        <translation>escriba la dirección IPv6 del servidor entre corchetes: [%1]:3334</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no host name</source>
        <translation>«%1» no tiene nombre de host</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a host name (expected host:port, e.g. localhost:3334)</source>
        <translation>«%1» no es un nombre de host (se esperaba host:puerto, p. ej. localhost:3334)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a port number (1 to 65535)</source>
        <translation>«%1» no es un número de puerto (1 a 65535)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is a URL: give the server as host:port, e.g. localhost:3334 (or tls://host:port over TLS)</source>
        <translation>«%1» es una URL: indique el servidor como host:puerto, p. ej. localhost:3334 (o tls://host:puerto por TLS)</translation>
    </message>
</context>
<context>
    <name>ServerHistoryDialog</name>
    <message>
        <source>Server history</source>
        <translation>Historial del servidor</translation>
    </message>
    <message>
        <source>Vehicle</source>
        <translation>Vehículo</translation>
    </message>
    <message>
        <source>From (UTC)</source>
        <translation>Desde (UTC)</translation>
    </message>
    <message>
        <source>To (UTC)</source>
        <translation>Hasta (UTC)</translation>
    </message>
    <message>
        <source>Last hour</source>
        <translation>Última hora</translation>
    </message>
    <message>
        <source>Fetch and replay</source>
        <translation>Obtener y reproducir</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Cerrar</translation>
    </message>
</context>
<context>
    <name>ServerZoneReply</name>
    <message>
        <source>the server gave no reason</source>
        <translation>el servidor no indicó ningún motivo</translation>
    </message>
</context>
<context>
    <name>SetNfzChecksCommand</name>
    <message>
        <source>Check aerodrome zones</source>
        <translation>Comprobar zonas de aeródromo</translation>
    </message>
    <message>
        <source>Do not check aerodrome zones</source>
        <translation>No comprobar zonas de aeródromo</translation>
    </message>
    <message>
        <source>Check custom zones</source>
        <translation>Comprobar zonas personalizadas</translation>
    </message>
    <message>
        <source>Do not check custom zones</source>
        <translation>No comprobar zonas personalizadas</translation>
    </message>
</context>
<context>
    <name>ShortcutHelp</name>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Atajos de teclado</translation>
    </message>
    <message>
        <source>On the map</source>
        <translation>En el mapa</translation>
    </message>
    <message>
        <source>Esc closes this help.</source>
        <translation>Esc cierra esta ayuda.</translation>
    </message>
</context>
<context>
    <name>Shortcuts</name>
    <message>
        <source>Pan the map (Shift: faster)</source>
        <translation>Desplazar el mapa (Mayús: más rápido)</translation>
    </message>
    <message>
        <source>Zoom in / out (also the mouse wheel and pinch)</source>
        <translation>Acercar / alejar (también con la rueda del ratón y pellizcando)</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Arrastrar</translation>
    </message>
    <message>
        <source>Pan the map</source>
        <translation>Desplazar el mapa</translation>
    </message>
    <message>
        <source>Shift+Drag</source>
        <translation>Mayús+Arrastrar</translation>
    </message>
    <message>
        <source>Select waypoints in a rectangle (Ctrl+Shift adds)</source>
        <translation>Seleccionar waypoints en un rectángulo (Ctrl+Mayús añade)</translation>
    </message>
    <message>
        <source>Click</source>
        <translation>Clic</translation>
    </message>
    <message>
        <source>Add a waypoint; on a leg: insert one; on a waypoint: select (Ctrl toggles, Shift extends)</source>
        <translation>Añadir un waypoint; sobre un tramo: insertar uno; sobre un waypoint: seleccionar (Ctrl alterna, Mayús amplía)</translation>
    </message>
    <message>
        <source>Drag a waypoint</source>
        <translation>Arrastrar un waypoint</translation>
    </message>
    <message>
        <source>Move it, or the whole selection</source>
        <translation>Moverlo, o toda la selección</translation>
    </message>
    <message>
        <source>Show or hide this help</source>
        <translation>Mostrar u ocultar esta ayuda</translation>
    </message>
    <message>
        <source>Login page</source>
        <translation>Página de inicio de sesión</translation>
    </message>
    <message>
        <source>Mission page</source>
        <translation>Página de misión</translation>
    </message>
    <message>
        <source>Live telemetry page</source>
        <translation>Página de telemetría en vivo</translation>
    </message>
    <message>
        <source>Save the route on the server</source>
        <translation>Guardar la ruta en el servidor</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Deshacer</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Rehacer</translation>
    </message>
    <message>
        <source>Delete the selected waypoints</source>
        <translation>Eliminar los waypoints seleccionados</translation>
    </message>
    <message>
        <source>Process the route on the server</source>
        <translation>Procesar la ruta en el servidor</translation>
    </message>
    <message>
        <source>Choose the map source</source>
        <translation>Elegir la fuente del mapa</translation>
    </message>
    <message>
        <source>Focus the map (then arrows and +/− move it)</source>
        <translation>Enfocar el mapa (después las flechas y +/− lo mueven)</translation>
    </message>
    <message>
        <source>Full screen on or off</source>
        <translation>Activar o desactivar pantalla completa</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Salir</translation>
    </message>
</context>
<context>
    <name>SortieFormat</name>
    <message>
        <source>not a valid UgCS %1</source>
        <translation>no es un mensaje UgCS %1 válido</translation>
    </message>
    <message>
        <source>missing &quot;AGL&quot; or &quot;AMSL&quot;</source>
        <translation>falta «AGL» o «AMSL»</translation>
    </message>
    <message>
        <source>expected &quot;AGL&quot; or &quot;AMSL&quot;</source>
        <translation>se esperaba «AGL» o «AMSL»</translation>
    </message>
    <message>
        <source>unknown value &quot;%1&quot;</source>
        <translation>valor desconocido «%1»</translation>
    </message>
    <message>
        <source>latitude out of range</source>
        <translation>latitud fuera de rango</translation>
    </message>
    <message>
        <source>longitude out of range</source>
        <translation>longitud fuera de rango</translation>
    </message>
    <message>
        <source>latitude/longitude out of range</source>
        <translation>latitud/longitud fuera de rango</translation>
    </message>
    <message>
        <source>expected &quot;altitude&quot; or &quot;groundSampleDistance&quot;</source>
        <translation>se esperaba «altitude» o «groundSampleDistance»</translation>
    </message>
    <message>
        <source>no figure type %1</source>
        <translation>no existe el tipo de figura %1</translation>
    </message>
    <message>
        <source>unknown segment type &quot;%1&quot;</source>
        <translation>tipo de segmento desconocido «%1»</translation>
    </message>
    <message>
        <source>expected &quot;none&quot; or &quot;returnHome&quot;</source>
        <translation>se esperaba «none» o «returnHome»</translation>
    </message>
    <message>
        <source>not a Sortie mission file (&quot;format&quot; is not &quot;sortie-mission&quot;)</source>
        <translation>no es un archivo de misión de Sortie («format» no es «sortie-mission»)</translation>
    </message>
    <message>
        <source>schema version %1 does not exist</source>
        <translation>la versión de esquema %1 no existe</translation>
    </message>
    <message>
        <source>written by a newer Sortie (schema %1); this one reads up to schema %2</source>
        <translation>escrito por una versión más reciente de Sortie (esquema %1); esta lee hasta el esquema %2</translation>
    </message>
    <message>
        <source>expected a date and time in UTC, e.g. 2026-06-06T18:00:00Z</source>
        <translation>se esperaba una fecha y hora en UTC, p. ej. 2026-06-06T18:00:00Z</translation>
    </message>
    <message>
        <source>an authorisation needs the zone&apos;s identifier</source>
        <translation>una autorización necesita el identificador de la zona</translation>
    </message>
</context>
<context>
    <name>StatusBar</name>
    <message>
        <source>zoom %1</source>
        <translation>zoom %1</translation>
    </message>
</context>
<context>
    <name>TelemetryFieldNames</name>
    <message>
        <source>Latitude</source>
        <translation>Latitud</translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation>Longitud</translation>
    </message>
    <message>
        <source>Altitude (AMSL)</source>
        <translation>Altitud (s. n. m.)</translation>
    </message>
    <message>
        <source>Altitude above home</source>
        <translation>Altitud sobre el punto de inicio</translation>
    </message>
    <message>
        <source>Roll</source>
        <translation>Alabeo</translation>
    </message>
    <message>
        <source>Pitch</source>
        <translation>Cabeceo</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Rumbo</translation>
    </message>
    <message>
        <source>Course</source>
        <translation>Derrota</translation>
    </message>
    <message>
        <source>Ground speed</source>
        <translation>Velocidad respecto al suelo</translation>
    </message>
    <message>
        <source>Air speed</source>
        <translation>Velocidad aerodinámica</translation>
    </message>
    <message>
        <source>Vertical speed</source>
        <translation>Velocidad vertical</translation>
    </message>
    <message>
        <source>Battery voltage</source>
        <translation>Tensión de la batería</translation>
    </message>
    <message>
        <source>Battery current</source>
        <translation>Corriente de la batería</translation>
    </message>
    <message>
        <source>Battery remaining</source>
        <translation>Batería restante</translation>
    </message>
    <message>
        <source>GPS fix</source>
        <translation>Fix GPS</translation>
    </message>
    <message>
        <source>Satellites</source>
        <translation>Satélites</translation>
    </message>
    <message>
        <source>HDOP</source>
        <translation>HDOP</translation>
    </message>
    <message>
        <source>Home latitude</source>
        <translation>Latitud del punto de inicio</translation>
    </message>
    <message>
        <source>Home longitude</source>
        <translation>Longitud del punto de inicio</translation>
    </message>
    <message>
        <source>Home altitude (AMSL)</source>
        <translation>Altitud del punto de inicio (s. n. m.)</translation>
    </message>
    <message>
        <source>Armed</source>
        <translation>Armado</translation>
    </message>
    <message>
        <source>Flight mode</source>
        <translation>Modo de vuelo</translation>
    </message>
    <message>
        <source>Mission state</source>
        <translation>Estado de la misión</translation>
    </message>
    <message>
        <source>Current waypoint</source>
        <translation>Punto de ruta actual</translation>
    </message>
    <message>
        <source>Waypoints reached</source>
        <translation>Puntos de ruta alcanzados</translation>
    </message>
    <message>
        <source>Waypoints on board</source>
        <translation>Puntos de ruta a bordo</translation>
    </message>
    <message>
        <source>Fence breached</source>
        <translation>Geovalla rebasada</translation>
    </message>
    <message>
        <source>Fence breaches</source>
        <translation>Rebases de geovalla</translation>
    </message>
</context>
<context>
    <name>TelemetryPage</name>
    <message>
        <source>Vehicles</source>
        <translation>Vehículos</translation>
    </message>
    <message>
        <source>No vehicles. Log in to a server or connect a VCI vehicle.</source>
        <translation>No hay vehículos. Inicie sesión en un servidor o conecte un vehículo VCI.</translation>
    </message>
    <message>
        <source>Command together with the other ticked vehicles</source>
        <translation>Dar órdenes junto con los demás vehículos marcados</translation>
    </message>
    <message>
        <source>Vehicle %1</source>
        <translation>Vehículo %1</translation>
    </message>
    <message>
        <source>A vehicle reached directly over VCI: tcp://host:port or serial:///dev/ttyX?baud=57600</source>
        <translation>Un vehículo conectado directamente por VCI: tcp://host:puerto o serial:///dev/ttyX?baud=57600</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Añadir</translation>
    </message>
    <message>
        <source>Fit all</source>
        <translation>Ver todos</translation>
    </message>
    <message>
        <source>Show every vehicle on the map</source>
        <translation>Mostrar todos los vehículos en el mapa</translation>
    </message>
    <message>
        <source>Follow</source>
        <translation>Seguir</translation>
    </message>
    <message>
        <source>Keep the chosen vehicle in the middle of the map</source>
        <translation>Mantener el vehículo elegido en el centro del mapa</translation>
    </message>
    <message>
        <source>Fly %1 to %2?</source>
        <translation>¿Volar %1 a %2?</translation>
    </message>
    <message>
        <source>Plot this field too</source>
        <translation>Representar también este campo</translation>
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
        <translation>Quitar de la gráfica</translation>
    </message>
    <message>
        <source>All vehicles</source>
        <translation>Todos los vehículos</translation>
    </message>
    <message>
        <source>Compare these fields across every vehicle</source>
        <translation>Comparar estos campos entre todos los vehículos</translation>
    </message>
    <message>
        <source>Video</source>
        <translation>Vídeo</translation>
    </message>
    <message>
        <source>Show the chosen vehicle&apos;s video over the map</source>
        <translation>Mostrar el vídeo del vehículo elegido sobre el mapa</translation>
    </message>
</context>
<context>
    <name>TerrainFollow</name>
    <message>
        <source>Waiting for terrain data from %1</source>
        <translation>Esperando datos de terreno de %1</translation>
    </message>
    <message>
        <source>No terrain data %1 m along the pass (tried: %2): terrain following needs the ground everywhere</source>
        <translation>Sin datos de terreno a %1 m a lo largo de la pasada (se probó: %2): el seguimiento del terreno necesita el terreno en todas partes</translation>
    </message>
</context>
<context>
    <name>TerrainProfile</name>
    <message>
        <source>%1, point %2</source>
        <translation>%1, punto %2</translation>
    </message>
    <message>
        <source>Waypoint %1</source>
        <translation>Waypoint %1</translation>
    </message>
    <message>
        <source>Leg %1 (%2 → %3)</source>
        <translation>Tramo %1 (%2 → %3)</translation>
    </message>
</context>
<context>
    <name>TerrainRule</name>
    <message>
        <source>Waypoint %1</source>
        <translation>Waypoint %1</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 a %2</translation>
    </message>
    <message>
        <source>%1 m above the ground</source>
        <translation>a %1 m sobre el terreno</translation>
    </message>
    <message>
        <source>%1 m below the ground</source>
        <translation>a %1 m bajo el terreno</translation>
    </message>
    <message>
        <source> (too low from %1 m to %2 m along it)</source>
        <translation> (demasiado bajo de %1 m a %2 m de su inicio)</translation>
    </message>
    <message>
        <source>%1 flies %2 at %3 m along it%4, closer than the safe distance of %5 m.</source>
        <translation>%1 vuela %2 a %3 m de su inicio%4, más cerca que la distancia de seguridad de %5 m.</translation>
    </message>
    <message>
        <source>%1: no terrain data from %2 m to %3 m along it</source>
        <translation>%1: sin datos de terreno de %2 m a %3 m de su inicio</translation>
    </message>
    <message>
        <source>No terrain data from %1 m along %2 to %3 m along %4</source>
        <translation>Sin datos de terreno desde %1 m de %2 hasta %3 m de %4</translation>
    </message>
    <message>
        <source>%1 (tried: %2); the clearance there is not checked.</source>
        <translation>%1 (se probó: %2); allí no se comprueba el margen.</translation>
    </message>
    <message>
        <source>%1: the altitude is above home, but there is no terrain data at home (tried: %2), so the height above sea level is unknown.</source>
        <translation>%1: la altitud es sobre el punto de inicio, pero no hay datos del terreno en el punto de inicio (probado: %2), así que la altura sobre el nivel del mar es desconocida.</translation>
    </message>
    <message>
        <source>%1: the altitude is above the ground, but there is no terrain data there (tried: %2), so the height above sea level is unknown.</source>
        <translation>%1: la altitud es sobre el suelo, pero allí no hay datos del terreno (probado: %2), así que la altura sobre el nivel del mar es desconocida.</translation>
    </message>
    <message>
        <source>%1 flies up to %2 m above the ground at %3 m along it; the open category allows %4 m above the surface.</source>
        <translation>%1 vuela hasta %2 m sobre el suelo a %3 m de su inicio; la categoría abierta permite %4 m sobre la superficie.</translation>
    </message>
</context>
<context>
    <name>TileArea</name>
    <message>
        <source>The area is not a valid latitude/longitude box (south %1, west %2, north %3, east %4).</source>
        <translation>El área no es un rectángulo válido de latitud/longitud (sur %1, oeste %2, norte %3, este %4).</translation>
    </message>
    <message>
        <source>An area needs at least three corners (it has %1).</source>
        <translation>Un área necesita al menos tres esquinas (tiene %1).</translation>
    </message>
    <message>
        <source>Corner %1 of the area is not a latitude/longitude (%2, %3).</source>
        <translation>La esquina %1 del área no es una latitud/longitud (%2, %3).</translation>
    </message>
    <message>
        <source>The area&apos;s edge from corner %1 crosses the antimeridian: draw it as two areas.</source>
        <translation>El lado del área que parte de la esquina %1 cruza el antimeridiano: dibújela como dos áreas.</translation>
    </message>
    <message>
        <source>The area&apos;s edges from corner %1 and corner %2 cross: draw it without crossing.</source>
        <translation>Los lados del área desde la esquina %1 y la esquina %2 se cruzan: dibújela sin cruces.</translation>
    </message>
</context>
<context>
    <name>TileResponse</name>
    <message>
        <source>larger than %1 MiB: not read</source>
        <translation>mayor de %1 MiB: no se lee</translation>
    </message>
</context>
<context>
    <name>TileUrlTemplate</name>
    <message>
        <source>No tile URL template is set.</source>
        <translation>No se ha indicado ninguna plantilla de URL de teselas.</translation>
    </message>
    <message>
        <source>The tile URL template is not a valid URL: %1</source>
        <translation>La plantilla de URL de teselas no es una URL válida: %1</translation>
    </message>
    <message>
        <source>The tile URL template must start with http://, https:// or file://.</source>
        <translation>La plantilla de URL de teselas debe empezar por http://, https:// o file://.</translation>
    </message>
    <message>
        <source>The tile URL template needs {z}, {x} and {y} (or {-y}).</source>
        <translation>La plantilla de URL de teselas necesita {z}, {x} e {y} (o {-y}).</translation>
    </message>
</context>
<context>
    <name>TlsServerIdentity</name>
    <message>
        <source>this Qt has no TLS backend (%1)</source>
        <translation>este Qt no tiene motor TLS (%1)</translation>
    </message>
    <message>
        <source>%1 holds no PEM certificate</source>
        <translation>%1 no contiene ningún certificado PEM</translation>
    </message>
    <message>
        <source>%1 holds no unencrypted PEM RSA or EC private key</source>
        <translation>%1 no contiene ninguna clave privada PEM RSA o EC sin cifrar</translation>
    </message>
</context>
<context>
    <name>TlsVerdict</name>
    <message>
        <source>%1 sent no certificate</source>
        <translation>%1 no envió ningún certificado</translation>
    </message>
    <message>
        <source>the pinned fingerprint for %1 is not a SHA-256 fingerprint (64 hex digits): %2</source>
        <translation>la huella fijada para %1 no es una huella SHA-256 (64 dígitos hexadecimales): %2</translation>
    </message>
    <message>
        <source>%1 showed a certificate that is not the pinned one: pinned SHA-256 %2, shown SHA-256 %3</source>
        <translation>%1 mostró un certificado que no es el fijado: fijado SHA-256 %2, mostrado SHA-256 %3</translation>
    </message>
    <message>
        <source>the certificate of %1 has changed since it was first trusted: remembered SHA-256 %2, now SHA-256 %3. Someone may be in between; if the server&apos;s certificate was replaced on purpose, forget the remembered one</source>
        <translation>el certificado de %1 ha cambiado desde que se confió en él por primera vez: recordado SHA-256 %2, ahora SHA-256 %3. Puede haber alguien en medio; si el certificado del servidor se sustituyó a propósito, olvide el recordado</translation>
    </message>
    <message>
        <source>the certificate of %1 (SHA-256 %2) is not trusted by this system (%3), and there is no pinned or remembered one</source>
        <translation>este sistema no confía en el certificado de %1 (SHA-256 %2) (%3), y no hay ninguno fijado ni recordado</translation>
    </message>
</context>
<context>
    <name>UploadQuestion</name>
    <message>
        <source>Upload the route?</source>
        <translation>¿Subir la ruta?</translation>
    </message>
    <message>
        <source>Upload without saving</source>
        <translation>Subir sin guardar</translation>
    </message>
    <message>
        <source>Upload</source>
        <translation>Subir</translation>
    </message>
    <message>
        <source>Save and upload</source>
        <translation>Guardar y subir</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>UploadReview</name>
    <message>
        <source>%1 Fix it before %2.</source>
        <translation>%1 Corríjalo antes de %2.</translation>
    </message>
    <message numerus="yes">
        <source>%1 (and %n more error(s)) Fix them before %2.</source>
        <translation>
            <numerusform>%1 (y %n error más) Corríjalos antes de %2.</numerusform>
            <numerusform>%1 (y %n errores más) Corríjalos antes de %2.</numerusform>
        </translation>
    </message>
    <message>
        <source>Upload</source>
        <translation>Subir</translation>
    </message>
    <message>
        <source>uploading</source>
        <translation>subir</translation>
    </message>
    <message>
        <source>The route has edits that are not saved: the vehicle would fly what is on screen, not what the server holds.</source>
        <translation>La ruta tiene ediciones sin guardar: el vehículo volaría lo que hay en pantalla, no lo que guarda el servidor.</translation>
    </message>
    <message numerus="yes">
        <source>The route has %n warning(s):</source>
        <translation>
            <numerusform>La ruta tiene %n aviso:</numerusform>
            <numerusform>La ruta tiene %n avisos:</numerusform>
        </translation>
    </message>
    <message>
        <source>Upload to %1?</source>
        <translation>¿Subir a %1?</translation>
    </message>
    <message>
        <source>Saving</source>
        <translation>Guardado</translation>
    </message>
    <message>
        <source>saving</source>
        <translation>guardar</translation>
    </message>
</context>
<context>
    <name>UploadedFenceAlerts</name>
    <message>
        <source>route fence</source>
        <translation>geocerca de la ruta</translation>
    </message>
</context>
<context>
    <name>ValidationGate</name>
    <message numerus="yes">
        <source>%1 refused: the route has %n validation error(s). %2 Fix them, or override explicitly.</source>
        <translation>
            <numerusform>Operación rechazada (%1): la ruta tiene %n error de validación. %2 Corríjalo o fuerce la operación explícitamente.</numerusform>
            <numerusform>Operación rechazada (%1): la ruta tiene %n errores de validación. %2 Corríjalos o fuerce la operación explícitamente.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>VciConnection</name>
    <message>
        <source>the connection to the vehicle was closed</source>
        <translation>se cerró la conexión con el vehículo</translation>
    </message>
    <message>
        <source>the device was closed</source>
        <translation>se cerró el dispositivo</translation>
    </message>
    <message>
        <source>the device was destroyed</source>
        <translation>se destruyó el dispositivo</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid VCI URI</source>
        <translation>«%1» no es un URI de VCI válido</translation>
    </message>
    <message>
        <source>a ground station does not send NOTIFY</source>
        <translation>una estación de tierra no envía NOTIFY</translation>
    </message>
    <message>
        <source>not connected to the vehicle</source>
        <translation>sin conexión con el vehículo</translation>
    </message>
    <message>
        <source>no answer in time (it waited behind other requests)</source>
        <translation>sin respuesta a tiempo (esperó detrás de otras solicitudes)</translation>
    </message>
    <message>
        <source>writing to the vehicle failed: %1</source>
        <translation>falló la escritura en el vehículo: %1</translation>
    </message>
    <message>
        <source>the vehicle sent an answer (%1) to no request</source>
        <translation>el vehículo envió una respuesta (%1) que no corresponde a ninguna solicitud</translation>
    </message>
    <message>
        <source>unreadable message from the vehicle at byte %1: %2</source>
        <translation>mensaje ilegible del vehículo en el byte %1: %2</translation>
    </message>
    <message>
        <source>%1: the vehicle answered %2 %3</source>
        <translation>%1: el vehículo respondió %2 %3</translation>
    </message>
    <message>
        <source>the vehicle did not answer in time</source>
        <translation>el vehículo no respondió a tiempo</translation>
    </message>
</context>
<context>
    <name>VciEndpoint</name>
    <message>
        <source>&quot;%1&quot; is not a URL: %2</source>
        <translation>«%1» no es una URL: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names no serial device</source>
        <translation>«%1» no indica ningún dispositivo serie</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: unknown serial setting &quot;%2&quot; (baud, databits, parity, stopbits, flow)</source>
        <translation>«%1»: ajuste serie desconocido «%2» (baud, databits, parity, stopbits, flow)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2=%3 is not a valid value</source>
        <translation>«%1»: %2=%3 no es un valor válido</translation>
    </message>
    <message>
        <source>&quot;%1&quot; needs a host and a port: %2://host:port</source>
        <translation>«%1» necesita un host y un puerto: %2://host:puerto</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: unknown setting &quot;%2&quot; (vci+tls:// knows sha256=)</source>
        <translation>«%1»: ajuste desconocido «%2» (vci+tls:// conoce sha256=)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: sha256=%2 is not a SHA-256 fingerprint (64 hex digits)</source>
        <translation>«%1»: sha256=%2 no es una huella SHA-256 (64 dígitos hexadecimales)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: use tcp://host:port, vci+tls://host:port or serial:/dev/name</source>
        <translation>«%1»: use tcp://host:puerto, vci+tls://host:puerto o serial:/dev/nombre</translation>
    </message>
</context>
<context>
    <name>VciFenceBuilder</name>
    <message>
        <source>zone &apos;%1&apos;: its AGL limits need the ground under it, which no terrain source has; a vehicle cannot be given it</source>
        <translation>zona «%1»: sus límites AGL necesitan el terreno bajo ella, que ninguna fuente de terreno tiene; no se puede dar a un vehículo</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: no ground under it, so its AGL limits were dropped (the vehicle keeps out of the whole column)</source>
        <translation>zona «%1»: no hay terreno bajo ella, así que se descartaron sus límites AGL (el vehículo se mantiene fuera de toda la columna)</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: over ground from %2 to %3 m its AGL limits leave no room in AMSL</source>
        <translation>zona «%1»: sobre un terreno de %2 a %3 m, sus límites AGL no dejan espacio en AMSL</translation>
    </message>
    <message>
        <source>%1 (hole %2)</source>
        <translation>%1 (hueco %2)</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: its holes are closed on the vehicle (a fence polygon has none)</source>
        <translation>zona «%1»: sus huecos se cierran en el vehículo (un polígono de geocerca no tiene)</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: a cone that narrows to a point cannot keep a vehicle in</source>
        <translation>zona «%1»: un cono que se estrecha hasta un punto no puede mantener dentro a un vehículo</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: its cone is a cylinder of radius %2 m on the vehicle</source>
        <translation>zona «%1»: en el vehículo, su cono es un cilindro de %2 m de radio</translation>
    </message>
    <message>
        <source>route fence</source>
        <translation>geocerca de la ruta</translation>
    </message>
    <message>
        <source>the fence cannot be sent: %1</source>
        <translation>no se puede enviar la geocerca: %1</translation>
    </message>
    <message numerus="yes">
        <source>fence: %1 of the route&apos;s own, %n airspace zone(s) near it; on a breach the vehicle will %2</source>
        <translation>
            <numerusform>geocerca: %1 de la propia ruta, %n zona del espacio aéreo cercana; si la viola, el vehículo va a %2</numerusform>
            <numerusform>geocerca: %1 de la propia ruta, %n zonas del espacio aéreo cercanas; si la viola, el vehículo va a %2</numerusform>
        </translation>
    </message>
    <message>
        <source>return home</source>
        <translation>volver al origen</translation>
    </message>
    <message>
        <source>land</source>
        <translation>aterrizar</translation>
    </message>
    <message>
        <source>hold</source>
        <translation>mantener la posición</translation>
    </message>
    <message>
        <source>the fence cannot be made: its zones are not the airspace&apos;s</source>
        <translation>no se puede crear la geocerca: sus zonas no son del espacio aéreo</translation>
    </message>
</context>
<context>
    <name>VciMissionPlanner</name>
    <message>
        <source>the route has no waypoints to fly</source>
        <translation>la ruta no tiene waypoints que volar</translation>
    </message>
</context>
<context>
    <name>VciTransport</name>
    <message>
        <source>closed by the operator</source>
        <translation>cerrada por el operador</translation>
    </message>
    <message>
        <source>reconnecting at the operator&apos;s request</source>
        <translation>reconectando a petición del operador</translation>
    </message>
    <message>
        <source>the vehicle closed the connection</source>
        <translation>el vehículo cerró la conexión</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <translation>no se puede abrir %1: %2</translation>
    </message>
    <message>
        <source>not connected over TLS: %1</source>
        <translation>sin conexión por TLS: %1</translation>
    </message>
</context>
<context>
    <name>VciVehicleLink</name>
    <message>
        <source>connection to %1 lost: %2</source>
        <translation>conexión con %1 perdida: %2</translation>
    </message>
    <message>
        <source>disconnected by the operator</source>
        <translation>desconectado por el operador</translation>
    </message>
    <message>
        <source>left its fence &apos;%1&apos;</source>
        <translation>salió de su geocerca «%1»</translation>
    </message>
    <message>
        <source>entered the exclusion zone &apos;%1&apos;</source>
        <translation>entró en la zona de exclusión «%1»</translation>
    </message>
    <message>
        <source>returning home</source>
        <extracomment>What a vehicle does after a fence breach: &quot;fence breach: left its fence &apos;A&apos;; returning home&quot;.</extracomment>
        <translation>volviendo al origen</translation>
    </message>
    <message>
        <source>action unknown</source>
        <extracomment>After a fence breach, the vehicle named no action: &quot;fence breach: left its fence &apos;A&apos;; action unknown&quot;.</extracomment>
        <translation>acción desconocida</translation>
    </message>
    <message>
        <source>fence breach: %1; %2</source>
        <translation>violación de geocerca: %1; %2</translation>
    </message>
    <message>
        <source>the ground under the route did not arrive from %1 in %2 s</source>
        <translation>el terreno bajo la ruta no llegó de %1 en %2 s</translation>
    </message>
    <message>
        <source>the vehicle refused the fence: %1</source>
        <translation>el vehículo rechazó la geocerca: %1</translation>
    </message>
    <message>
        <source>the fence could not be read back: %1</source>
        <translation>no se pudo leer de vuelta la geocerca: %1</translation>
    </message>
    <message>
        <source>the vehicle&apos;s fence cannot be read: %1</source>
        <translation>no se puede leer la geocerca del vehículo: %1</translation>
    </message>
    <message>
        <source>the vehicle holds another fence than the one sent (%1 items sent, %2 held)</source>
        <translation>el vehículo contiene una geocerca distinta de la enviada (%1 elementos enviados, %2 contenidos)</translation>
    </message>
    <message>
        <source>the vehicle&apos;s mission cannot be read: %1</source>
        <translation>no se puede leer la misión del vehículo: %1</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a parameter name</source>
        <translation>«%1» no es un nombre de parámetro</translation>
    </message>
    <message>
        <source>landing</source>
        <extracomment>What a vehicle does after a fence breach: &quot;fence breach: left its fence &apos;A&apos;; landing&quot;.</extracomment>
        <translation>aterrizando</translation>
    </message>
    <message>
        <source>holding</source>
        <extracomment>What a vehicle does after a fence breach: &quot;fence breach: left its fence &apos;A&apos;; holding&quot;.</extracomment>
        <translation>manteniendo posición</translation>
    </message>
    <message>
        <source>the fence cannot be made: this link was given no fence builder</source>
        <translation>no se puede crear la geocerca: este enlace no recibió ningún generador de geocercas</translation>
    </message>
    <message>
        <source>%1: first secure connection; its certificate is now trusted and remembered. Compare its SHA-256 fingerprint with the vehicle&apos;s: %2</source>
        <translation>%1: primera conexión segura; su certificado es ahora de confianza y queda recordado. Compare su huella SHA-256 con la del vehículo: %2</translation>
    </message>
    <message>
        <source>a photo report was not understood: %1</source>
        <translation>no se entendió un informe de foto: %1</translation>
    </message>
</context>
<context>
    <name>Vehicle</name>
    <message>
        <source>mode %1</source>
        <translation>modo %1</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a flight mode</source>
        <translation>«%1» no es un modo de vuelo</translation>
    </message>
    <message>
        <source>takeoff to %1 m</source>
        <translation>despegue a %1 m</translation>
    </message>
    <message>
        <source>return home</source>
        <translation>volver al origen</translation>
    </message>
</context>
<context>
    <name>VerticalDatum</name>
    <message>
        <source>ellipsoidal (%1)</source>
        <translation>elipsoidal (%1)</translation>
    </message>
    <message>
        <source>orthometric (%1)</source>
        <translation>ortométrica (%1)</translation>
    </message>
    <message>
        <source>not stated</source>
        <translation>no indicada</translation>
    </message>
</context>
<context>
    <name>VideoPanel</name>
    <message>
        <source>rtsp://, udp://:5600 or an .sdp file</source>
        <translation>rtsp://, udp://:5600 o un archivo .sdp</translation>
    </message>
    <message>
        <source>This vehicle&apos;s video: empty plays the stream the vehicle publishes; a URL typed here overrides it and is remembered.</source>
        <translation>El vídeo de este vehículo: vacío reproduce el flujo que publica el vehículo; una URL escrita aquí lo sustituye y se recuerda.</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Grabar</translation>
    </message>
    <message>
        <source>Recording to %1</source>
        <translation>Grabando en %1</translation>
    </message>
    <message>
        <source>Record this video as received, beside the flight log</source>
        <translation>Grabar este vídeo tal como llega, junto al registro de vuelo</translation>
    </message>
    <message>
        <source>Map</source>
        <translation>Mapa</translation>
    </message>
    <message>
        <source>Swap</source>
        <translation>Intercambiar</translation>
    </message>
</context>
<context>
    <name>VideoSource</name>
    <message>
        <source>latency &apos;%1&apos;: expected milliseconds from 0 to 10000</source>
        <translation>latencia «%1»: se esperan milisegundos de 0 a 10000</translation>
    </message>
    <message>
        <source>codec &apos;%1&apos;: expected h264 or h265</source>
        <translation>códec «%1»: se espera h264 o h265</translation>
    </message>
    <message>
        <source>payload &apos;%1&apos;: expected a dynamic RTP payload type from 96 to 127</source>
        <translation>payload «%1»: se espera un tipo de payload RTP dinámico de 96 a 127</translation>
    </message>
    <message>
        <source>unknown option &apos;%1&apos;</source>
        <translation>opción desconocida «%1»</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an IP address to listen on</source>
        <translation>«%1» no es una dirección IP en la que escuchar</translation>
    </message>
    <message>
        <source>port %1 is out of range</source>
        <translation>el puerto %1 está fuera de rango</translation>
    </message>
    <message>
        <source>an RTSP URL needs a host: rtsp://host:8554/path</source>
        <translation>una URL RTSP necesita un host: rtsp://host:8554/ruta</translation>
    </message>
    <message>
        <source>port 0 is out of range</source>
        <translation>el puerto 0 está fuera de rango</translation>
    </message>
    <message>
        <source>SDP file %1: %2</source>
        <translation>Archivo SDP %1: %2</translation>
    </message>
    <message>
        <source>RTSP over TCP %1</source>
        <translation>RTSP sobre TCP %1</translation>
    </message>
    <message>
        <source>RTSP %1</source>
        <translation>RTSP %1</translation>
    </message>
    <message>
        <source>RTP/UDP %1 port %2</source>
        <translation>RTP/UDP %1 puerto %2</translation>
    </message>
    <message>
        <source>MPEG-TS/UDP port %1</source>
        <translation>MPEG-TS/UDP puerto %1</translation>
    </message>
    <message>
        <source>no video URL</source>
        <translation>sin URL de vídeo</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a URL</source>
        <translation>«%1» no es una URL</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a video URL Sortie plays: use rtsp://, rtspt://, udp://, udp+ts:// or an .sdp file</source>
        <translation>«%1» no es una URL de vídeo que Sortie reproduzca: use rtsp://, rtspt://, udp://, udp+ts:// o un archivo .sdp</translation>
    </message>
    <message>
        <source>SDP file %1 cannot be read as SDP</source>
        <translation>El archivo SDP %1 no se puede leer como SDP</translation>
    </message>
    <message>
        <source>SDP file %1: port %2 is out of range</source>
        <translation>Archivo SDP %1: el puerto %2 está fuera de rango</translation>
    </message>
    <message>
        <source>SDP file %1: the video has no payload type</source>
        <translation>Archivo SDP %1: el vídeo no tiene tipo de payload</translation>
    </message>
    <message>
        <source>SDP file %1: payload type %2 is not a dynamic one (96 to 127)</source>
        <translation>Archivo SDP %1: el tipo de payload %2 no es dinámico (96 a 127)</translation>
    </message>
    <message>
        <source>SDP file %1: no rtpmap for payload %2</source>
        <translation>Archivo SDP %1: sin rtpmap para el payload %2</translation>
    </message>
    <message>
        <source>SDP file %1: the video is %2, not H.264 or H.265</source>
        <translation>Archivo SDP %1: el vídeo es %2, no H.264 ni H.265</translation>
    </message>
    <message>
        <source>SDP file %1 describes no video</source>
        <translation>El archivo SDP %1 no describe ningún vídeo</translation>
    </message>
</context>
<context>
    <name>WaypointAction</name>
    <message>
        <source>Wait for operator</source>
        <translation>Esperar al operador</translation>
    </message>
    <message>
        <source>Wait %1 s</source>
        <translation>Esperar %1 s</translation>
    </message>
    <message>
        <source>Heading %1°%2</source>
        <translation>Rumbo %1°%2</translation>
    </message>
    <message>
        <source> from course</source>
        <translation> respecto a la trayectoria</translation>
    </message>
    <message>
        <source>Look at %1, %2</source>
        <translation>Mirar a %1, %2</translation>
    </message>
    <message>
        <source>Take photo</source>
        <translation>Tomar foto</translation>
    </message>
    <message>
        <source>Start video</source>
        <translation>Iniciar vídeo</translation>
    </message>
    <message>
        <source>Stop video</source>
        <translation>Detener vídeo</translation>
    </message>
    <message>
        <source>Toggle video</source>
        <translation>Alternar vídeo</translation>
    </message>
    <message>
        <source>Photo every %1 s</source>
        <translation>Foto cada %1 s</translation>
    </message>
    <message>
        <source>Photo every %1 m</source>
        <translation>Foto cada %1 m</translation>
    </message>
    <message>
        <source>Stop photos</source>
        <translation>Detener fotos</translation>
    </message>
    <message>
        <source>Panorama %1°</source>
        <translation>Panorámica %1°</translation>
    </message>
    <message>
        <source>tilt %1°</source>
        <translation>inclinación %1°</translation>
    </message>
    <message>
        <source>roll %1°</source>
        <translation>alabeo %1°</translation>
    </message>
    <message>
        <source>yaw %1°</source>
        <translation>guiñada %1°</translation>
    </message>
    <message>
        <source>zoom %1</source>
        <translation>zoom %1</translation>
    </message>
    <message>
        <source>Gimbal (nothing set)</source>
        <translation>Gimbal (nada fijado)</translation>
    </message>
</context>
<context>
    <name>WaypointTable</name>
    <message numerus="yes">
        <source>%n selected:</source>
        <translation>
            <numerusform>%n seleccionado:</numerusform>
            <numerusform>%n seleccionados:</numerusform>
        </translation>
    </message>
    <message>
        <source>alt m</source>
        <translation>alt m</translation>
    </message>
    <message>
        <source>Set</source>
        <translation>Fijar</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>Altitude above ground (AGL) or above mean sea level (AMSL)</source>
        <translation>Altitud sobre el terreno (AGL) o sobre el nivel medio del mar (AMSL)</translation>
    </message>
    <message>
        <source>Heights:</source>
        <translation>Alturas:</translation>
    </message>
    <message>
        <source>as set</source>
        <translation>como están</translation>
    </message>
    <message>
        <source>all AMSL</source>
        <translation>todas AMSL</translation>
    </message>
    <message>
        <source>all AGL</source>
        <translation>todas AGL</translation>
    </message>
    <message>
        <source>AMSL and AGL are converted through the ground under each waypoint</source>
        <translation>AMSL y AGL se convierten a través del terreno bajo cada waypoint</translation>
    </message>
    <message>
        <source>ground: %1</source>
        <translation>terreno: %1</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>Latitude</source>
        <translation>Latitud</translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation>Longitud</translation>
    </message>
    <message>
        <source>Alt</source>
        <translation>Alt</translation>
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
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Ground</source>
        <translation>Terreno</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Velocidad</translation>
    </message>
    <message>
        <source>Actions</source>
        <translation>Acciones</translation>
    </message>
    <message>
        <source>Area scan</source>
        <translation>Escaneo de área</translation>
    </message>
</context>
<context>
    <name>WplFormat</name>
    <message>
        <source>not a waypoint file: expected &quot;QGC WPL 110&quot;, found &quot;%1&quot;</source>
        <translation>no es un archivo de waypoints: se esperaba «QGC WPL 110», se encontró «%1»</translation>
    </message>
    <message>
        <source>unsupported waypoint file version &quot;%1&quot;; Sortie reads QGC WPL 110</source>
        <translation>versión de archivo de waypoints no compatible «%1»; Sortie lee QGC WPL 110</translation>
    </message>
    <message>
        <source>expected 12 tab-separated fields, found %1</source>
        <translation>se esperaban 12 campos separados por tabuladores, se encontraron %1</translation>
    </message>
    <message>
        <source>field %1 (%2) is not a number: &quot;%3&quot;</source>
        <translation>el campo %1 (%2) no es un número: «%3»</translation>
    </message>
    <message>
        <source>field %1 (%2) must be a whole number, found %3</source>
        <translation>el campo %1 (%2) debe ser un número entero, se encontró %3</translation>
    </message>
    <message>
        <source>item %1 where item %2 was expected</source>
        <translation>elemento %1 donde se esperaba el elemento %2</translation>
    </message>
    <message>
        <source>the home position %1, %2 is not a position</source>
        <translation>la posición de origen %1, %2 no es una posición</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>el archivo está vacío</translation>
    </message>
    <message>
        <source>the file has no items, not even the home position</source>
        <translation>el archivo no tiene elementos, ni siquiera la posición de origen</translation>
    </message>
    <message>
        <source>The route has no home position: the first point was written as home, at 0 m AMSL.</source>
        <translation>La ruta no tiene posición de origen: el primer punto se escribió como origen, a 0 m AMSL.</translation>
    </message>
</context>
<context>
    <name>WpmlDocumentReader</name>
    <message>
        <source>malformed XML: %1</source>
        <translation>XML mal formado: %1</translation>
    </message>
    <message>
        <source>%1 is not a number: &quot;%2&quot;</source>
        <translation>%1 no es un número: «%2»</translation>
    </message>
    <message>
        <source>%1 is not a whole number: &quot;%2&quot;</source>
        <translation>%1 no es un número entero: «%2»</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; (written as &quot;%3&quot;)</source>
        <translation>%1 «%2» (escrito como «%3»)</translation>
    </message>
    <message>
        <source>coordinates &quot;%1&quot; are not longitude,latitude in degrees</source>
        <translation>las coordenadas «%1» no son longitud,latitud en grados</translation>
    </message>
    <message>
        <source>a waypoint index is not a whole number</source>
        <translation>un índice de waypoint no es un número entero</translation>
    </message>
</context>
<context>
    <name>ZipArchive</name>
    <message>
        <source>two of its entries have the same name</source>
        <translation>dos de sus entradas tienen el mismo nombre</translation>
    </message>
    <message>
        <source>its directory and its entries disagree</source>
        <translation>su directorio y sus entradas no coinciden</translation>
    </message>
    <message>
        <source>it has no ZIP directory (truncated, or not a ZIP file)</source>
        <translation>no tiene directorio ZIP (está truncado o no es un archivo ZIP)</translation>
    </message>
    <message>
        <source>the archive has no end of central directory</source>
        <translation>el archivo comprimido no tiene fin de directorio central</translation>
    </message>
    <message>
        <source>ZIP64 archives are not read</source>
        <translation>no se leen archivos ZIP64</translation>
    </message>
    <message>
        <source>a central directory record is damaged at byte %1</source>
        <translation>un registro del directorio central está dañado en el byte %1</translation>
    </message>
    <message>
        <source>an entry&apos;s local header lies outside the archive</source>
        <translation>la cabecera local de una entrada está fuera del archivo comprimido</translation>
    </message>
    <message>
        <source>the entries &quot;%1&quot; and &quot;%2&quot; share bytes in the archive (a ZIP bomb&apos;s trick): not read</source>
        <translation>las entradas «%1» y «%2» comparten bytes en el archivo comprimido (un truco de bomba ZIP): no se leen</translation>
    </message>
    <message>
        <source>not a ZIP archive: %1</source>
        <translation>no es un archivo ZIP: %1</translation>
    </message>
    <message>
        <source>not a readable ZIP archive: %1</source>
        <translation>no es un archivo ZIP legible: %1</translation>
    </message>
    <message>
        <source>the archive lists %1 entries, more than the %2 read</source>
        <translation>el archivo comprimido enumera %1 entradas, más de las %2 que se leen</translation>
    </message>
    <message>
        <source>the central directory lists %1 entries where libzip read %2</source>
        <translation>el directorio central enumera %1 entradas donde libzip leyó %2</translation>
    </message>
    <message>
        <source>the archive has no &quot;%1&quot;</source>
        <translation>el archivo comprimido no contiene «%1»</translation>
    </message>
    <message>
        <source>&quot;%1&quot; would inflate to %2 bytes, more than the %3 read from one entry</source>
        <translation>«%1» se descomprimiría en %2 bytes, más de los %3 que se leen de una entrada</translation>
    </message>
    <message>
        <source>reading &quot;%1&quot; would inflate the archive past %2 bytes in all</source>
        <translation>leer «%1» descomprimiría el archivo comprimido por encima de %2 bytes en total</translation>
    </message>
    <message>
        <source>&quot;%1&quot; claims %2 bytes from %3 compressed, more than %4 times: not inflated</source>
        <translation>«%1» declara %2 bytes a partir de %3 comprimidos, más de %4 veces: no se descomprime</translation>
    </message>
    <message>
        <source>&quot;%1&quot; cannot be read: %2</source>
        <translation>no se puede leer «%1»: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is damaged: %2</source>
        <translation>«%1» está dañado: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; holds a different size than the archive says (%2 bytes)</source>
        <translation>«%1» tiene un tamaño distinto del que indica el archivo comprimido (%2 bytes)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is damaged (its CRC does not match)</source>
        <translation>«%1» está dañado (su CRC no coincide)</translation>
    </message>
    <message>
        <source>the archive could not be written: %1</source>
        <translation>no se pudo escribir el archivo comprimido: %1</translation>
    </message>
    <message>
        <source>the archive could not be written: its bytes could not be read back</source>
        <translation>no se pudo escribir el archivo comprimido: no se pudieron leer de vuelta sus bytes</translation>
    </message>
</context>
<context>
    <name>Zone</name>
    <message>
        <source>above home</source>
        <translation>sobre el origen</translation>
    </message>
    <message>
        <source>server aerodrome</source>
        <translation>servidor (aeródromo)</translation>
    </message>
    <message>
        <source>server custom</source>
        <translation>servidor (personalizada)</translation>
    </message>
    <message>
        <source>vehicle fence</source>
        <translation>geocerca del vehículo</translation>
    </message>
    <message>
        <source>%1 polygon %2</source>
        <translation>%1, polígono %2</translation>
    </message>
    <message>
        <source>%1 circle %2</source>
        <translation>%1, círculo %2</translation>
    </message>
</context>
<context>
    <name>ZoneEditor</name>
    <message>
        <source>drawn on the map</source>
        <translation>dibujada en el mapa</translation>
    </message>
    <message>
        <source>vertex %1</source>
        <translation>vértice %1</translation>
    </message>
</context>
<context>
    <name>ZoneFiles</name>
    <message>
        <source>%1 was left out: %2</source>
        <translation>Se omitió %1: %2</translation>
    </message>
    <message>
        <source>unknown zone file type &quot;.%1&quot; (Sortie reads .plan, .geojson, .json and .kml)</source>
        <translation>tipo de archivo de zonas desconocido «.%1» (Sortie lee .plan, .geojson, .json y .kml)</translation>
    </message>
    <message>
        <source>volume %1: %2</source>
        <translation>volumen %1: %2</translation>
    </message>
    <message>
        <source>%1 zone %2 (&apos;%3&apos;) was left out: %4</source>
        <translation>Se omitió la zona %1 %2 («%3»): %4</translation>
    </message>
</context>
<context>
    <name>ZoneLegend</name>
    <message>
        <source>Prohibited</source>
        <translation>Prohibida</translation>
    </message>
    <message>
        <source>Authorisation needed</source>
        <translation>Requiere autorización</translation>
    </message>
    <message>
        <source>Conditions apply</source>
        <translation>Con condiciones</translation>
    </message>
    <message>
        <source>Information only</source>
        <translation>Solo información</translation>
    </message>
    <message>
        <source>Not in force during the flight</source>
        <translation>No vigente durante el vuelo</translation>
    </message>
</context>
<context>
    <name>ZonePanel</name>
    <message>
        <source>Load zones</source>
        <translation>Cargar zonas</translation>
    </message>
    <message>
        <source>Zones (*.geojson *.json *.kml *.plan)</source>
        <translation>Zonas (*.geojson *.json *.kml *.plan)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Zones (%1)</source>
        <translation>Zonas (%1)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Deshacer</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Rehacer</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Cargar…</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>Polígono</translation>
    </message>
    <message>
        <source>Click the corners on the map, then Create</source>
        <translation>Haga clic en las esquinas en el mapa y después en Crear</translation>
    </message>
    <message>
        <source>Circle</source>
        <translation>Círculo</translation>
    </message>
    <message>
        <source>Click the centre on the map; drag its handle for the radius</source>
        <translation>Haga clic en el centro en el mapa; arrastre su tirador para el radio</translation>
    </message>
    <message>
        <source>%1 corners</source>
        <translation>%1 esquinas</translation>
    </message>
    <message>
        <source>Create</source>
        <translation>Crear</translation>
    </message>
    <message>
        <source>Checked against the route when ticked</source>
        <translation>Se comprueba contra la ruta si está marcada</translation>
    </message>
    <message>
        <source>%1 · %2 – %3</source>
        <translation>%1 · %2 – %3</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Clase</translation>
    </message>
    <message>
        <source>Floor (m)</source>
        <translation>Base (m)</translation>
    </message>
    <message>
        <source>ground</source>
        <translation>suelo</translation>
    </message>
    <message>
        <source>Ceiling (m)</source>
        <translation>Techo (m)</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>ilimitado</translation>
    </message>
    <message>
        <source>Above</source>
        <translation>Sobre</translation>
    </message>
    <message>
        <source>Remove zone</source>
        <translation>Quitar zona</translation>
    </message>
    <message>
        <source>Warn within (m)</source>
        <translation>Avisar a menos de (m)</translation>
    </message>
    <message>
        <source>exclusion</source>
        <translation>exclusión</translation>
    </message>
    <message>
        <source>inclusion</source>
        <translation>inclusión</translation>
    </message>
    <message>
        <source>HOME</source>
        <translation>ORIGEN</translation>
    </message>
    <message>
        <source>Discard copy</source>
        <translation>Descartar copia</translation>
    </message>
    <message>
        <source>The server&apos;s zone stays as it is</source>
        <translation>La zona del servidor queda como está</translation>
    </message>
    <message>
        <source>Update on server</source>
        <translation>Actualizar en el servidor</translation>
    </message>
    <message>
        <source>Send to server</source>
        <translation>Enviar al servidor</translation>
    </message>
    <message>
        <source>Edit here</source>
        <translation>Editar aquí</translation>
    </message>
    <message>
        <source>Draw a copy to edit; Update on server stores it</source>
        <translation>Dibujar una copia para editarla; Actualizar en el servidor la guarda</translation>
    </message>
    <message>
        <source>Delete on server</source>
        <translation>Eliminar en el servidor</translation>
    </message>
    <message>
        <source>Waiting for the server…</source>
        <translation>Esperando al servidor…</translation>
    </message>
    <message>
        <source>Delete zone</source>
        <translation>Eliminar zona</translation>
    </message>
    <message>
        <source>Delete &apos;%1&apos; on the server, for every operator?</source>
        <translation>¿Eliminar «%1» en el servidor, para todos los operadores?</translation>
    </message>
    <message>
        <source>Zone feed URL (https://…)</source>
        <translation>URL del feed de zonas (https://…)</translation>
    </message>
    <message>
        <source>Fetching…</source>
        <translation>Descargando…</translation>
    </message>
    <message>
        <source>Fetch</source>
        <translation>Descargar</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Actualizar</translation>
    </message>
    <message>
        <source>Fetch the zone feed again from %1</source>
        <translation>Descargar de nuevo el feed de zonas de %1</translation>
    </message>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>Authorisation reference</source>
        <translation>Referencia de la autorización</translation>
    </message>
    <message>
        <source>Change</source>
        <translation>Cambiar</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Registrar</translation>
    </message>
    <message>
        <source>Kept with the route; the check then warns instead of refusing (empty: removed)</source>
        <translation>Se guarda con la ruta; la comprobación avisa en lugar de rechazar (vacío: se elimina)</translation>
    </message>
</context>
<context>
    <name>sortie</name>
    <message>
        <source>Sortie: mission planning and live telemetry for UgCS servers and VCI vehicles.</source>
        <translation>Sortie: planificación de misiones y telemetría en vivo para servidores UgCS y vehículos VCI.</translation>
    </message>
    <message>
        <source>Start the built-in simulator on this computer and connect to it.</source>
        <translation>Iniciar el simulador integrado en este equipo y conectarse a él.</translation>
    </message>
    <message>
        <source>User name to log in with.</source>
        <translation>Nombre de usuario con el que iniciar sesión.</translation>
    </message>
    <message>
        <source>Print the start-up time and memory in use, then quit (for benchmarks).</source>
        <translation>Mostrar el tiempo de arranque y la memoria en uso y salir (para pruebas de rendimiento).</translation>
    </message>
    <message>
        <source>Folder for autosaved edits (default: the application data folder; also SORTIE_AUTOSAVE_DIR).</source>
        <translation>Carpeta para las ediciones guardadas automáticamente (por defecto: la carpeta de datos de la aplicación; también SORTIE_AUTOSAVE_DIR).</translation>
    </message>
    <message>
        <source>An ADS-B receiver&apos;s SBS-1 feed for manned traffic, as dump1090 serves it (port 30003); also the setting traffic/sbsAddress.</source>
        <translation>Flujo SBS-1 de un receptor ADS-B para el tráfico tripulado, tal como lo sirve dump1090 (puerto 30003); también el ajuste traffic/sbsAddress.</translation>
    </message>
    <message>
        <source>--demo with only the server&apos;s three vehicles: &quot;parked&quot; (nothing moves) or &quot;flying&quot; (one flies, followed in the fly view); for benchmarks.</source>
        <translation>--demo solo con los tres vehículos del servidor: «parked» (nada se mueve) o «flying» (uno vuela, seguido en la vista de vuelo); para pruebas de rendimiento.</translation>
    </message>
    <message>
        <source>A DEM for the terrain: any raster GDAL reads (GeoTIFF, COG, Copernicus DEM, .hgt, ...) or a folder of them, asked before the server (also the setting terrain/demFolder).</source>
        <translation>Un DEM para el terreno: cualquier ráster que lea GDAL (GeoTIFF, COG, Copernicus DEM, .hgt, ...) o una carpeta de ellos, consultado antes que el servidor (también el ajuste terrain/demFolder).</translation>
    </message>
    <message>
        <source>UgCS server to connect to: host:port, or tls://host:port over TLS (a server behind a TLS terminator).</source>
        <translation>Servidor UgCS al que conectarse: host:puerto, o tls://host:puerto por TLS (un servidor detrás de un terminador TLS).</translation>
    </message>
    <message>
        <source>With --server tls://: the only certificate the server may show, as its SHA-256 fingerprint or a PEM file; remembered for that server.</source>
        <translation>Con --server tls://: el único certificado que el servidor puede mostrar, como huella SHA-256 o archivo PEM; se recuerda para ese servidor.</translation>
    </message>
    <message>
        <source>Connect a vehicle directly over VCI: tcp://host:port, vci+tls://host:port[?sha256=FINGERPRINT] or serial:///dev/ttyX?baud=57600.</source>
        <translation>Conectar un vehículo directamente por VCI: tcp://host:puerto, vci+tls://host:puerto[?sha256=HUELLA] o serial:///dev/ttyX?baud=57600.</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::Airspace</name>
    <message>
        <source>Reason: %1</source>
        <translation>Motivo: %1</translation>
    </message>
    <message>
        <source>When: %1</source>
        <translation>Cuándo: %1</translation>
    </message>
    <message>
        <source>Not in force during the planned flight.</source>
        <translation>No vigente durante el vuelo previsto.</translation>
    </message>
    <message>
        <source>Authority: %1</source>
        <translation>Autoridad: %1</translation>
    </message>
    <message>
        <source>%1: fetched from %2 %3</source>
        <translation>%1: descargado de %2 %3</translation>
    </message>
    <message>
        <source>%1: a file changed %2</source>
        <translation>%1: un archivo modificado %2</translation>
    </message>
    <message>
        <source>Some zone data is older than a week: fetch it or load it again before you fly.</source>
        <translation>Algunos datos de zonas tienen más de una semana: descárguelos o cárguelos de nuevo antes de volar.</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ServerZones</name>
    <message>
        <source>Zones across the ±180° meridian are not supported; the view was not asked about.</source>
        <translation>No se admiten zonas que crucen el meridiano de ±180°; no se consultó la vista.</translation>
    </message>
    <message>
        <source>The server&apos;s no-fly zones could not be read: %1</source>
        <translation>No se pudieron leer las zonas de no vuelo del servidor: %1</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not saved: not connected to the server.</source>
        <translation>La zona «%1» no se guardó: no hay conexión con el servidor.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; cannot be saved on the server: %2.</source>
        <translation>La zona «%1» no se puede guardar en el servidor: %2.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not saved: %2</source>
        <translation>La zona «%1» no se guardó: %2</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not saved: it is locked (%2)</source>
        <translation>La zona «%1» no se guardó: está bloqueada (%2)</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was saved, but the server&apos;s answer cannot be read back: %2</source>
        <translation>La zona «%1» se guardó, pero no se puede leer la respuesta del servidor: %2</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: it is not on the server.</source>
        <translation>La zona «%1» no se eliminó: no está en el servidor.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: aerodrome zones are the server&apos;s own.</source>
        <translation>La zona «%1» no se eliminó: las zonas de aeródromo son del propio servidor.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: not connected to the server.</source>
        <translation>La zona «%1» no se eliminó: no hay conexión con el servidor.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: it is locked (%2)</source>
        <translation>La zona «%1» no se eliminó: está bloqueada (%2)</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: %2</source>
        <translation>La zona «%1» no se eliminó: %2</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneAlertMonitor</name>
    <message>
        <source>%1 is inside &apos;%2&apos;</source>
        <translation>%1 está dentro de «%2»</translation>
    </message>
    <message>
        <source>%1 enters &apos;%2&apos;%3</source>
        <translation>%1 entra en «%2»%3</translation>
    </message>
    <message>
        <source>%1 is outside &apos;%2&apos;</source>
        <translation>%1 está fuera de «%2»</translation>
    </message>
    <message>
        <source>%1 leaves &apos;%2&apos;%3</source>
        <translation>%1 sale de «%2»%3</translation>
    </message>
    <message>
        <source> (its height there is unknown)</source>
        <translation> (se desconoce su altura allí)</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneEditor</name>
    <message>
        <source>A zone needs at least three corners.</source>
        <translation>Una zona necesita al menos tres esquinas.</translation>
    </message>
    <message>
        <source>This polygon cannot be a zone: %1</source>
        <translation>Este polígono no puede ser una zona: %1</translation>
    </message>
    <message>
        <source>Draw zone</source>
        <translation>Dibujar zona</translation>
    </message>
    <message>
        <source>A circular zone needs a centre and a radius above 0 m.</source>
        <translation>Una zona circular necesita un centro y un radio mayor que 0 m.</translation>
    </message>
    <message>
        <source>Draw circular zone</source>
        <translation>Dibujar zona circular</translation>
    </message>
    <message>
        <source>There is no drawn zone %1.</source>
        <translation>No hay ninguna zona dibujada %1.</translation>
    </message>
    <message>
        <source>Remove zone</source>
        <translation>Quitar zona</translation>
    </message>
    <message>
        <source>That is not a position.</source>
        <translation>Eso no es una posición.</translation>
    </message>
    <message>
        <source>A circle has only its centre to move.</source>
        <translation>De un círculo solo se puede mover el centro.</translation>
    </message>
    <message>
        <source>The zone has no corner %1.</source>
        <translation>La zona no tiene esquina %1.</translation>
    </message>
    <message>
        <source>Move zone corner</source>
        <translation>Mover esquina de zona</translation>
    </message>
    <message>
        <source>A corner can be added only to a polygon, on one of its edges.</source>
        <translation>Solo se puede añadir una esquina a un polígono, sobre uno de sus lados.</translation>
    </message>
    <message>
        <source>Add zone corner</source>
        <translation>Añadir esquina de zona</translation>
    </message>
    <message>
        <source>A zone keeps at least three corners.</source>
        <translation>Una zona conserva al menos tres esquinas.</translation>
    </message>
    <message>
        <source>Remove zone corner</source>
        <translation>Quitar esquina de zona</translation>
    </message>
    <message>
        <source>The radius must be above 0 m.</source>
        <translation>El radio debe ser mayor que 0 m.</translation>
    </message>
    <message>
        <source>Only a circular zone has a radius.</source>
        <translation>Solo una zona circular tiene radio.</translation>
    </message>
    <message>
        <source>Zone radius</source>
        <translation>Radio de zona</translation>
    </message>
    <message>
        <source>A zone needs a name.</source>
        <translation>Una zona necesita un nombre.</translation>
    </message>
    <message>
        <source>Rename zone</source>
        <translation>Renombrar zona</translation>
    </message>
    <message>
        <source>A zone is an exclusion or an inclusion zone, not &quot;%1&quot;.</source>
        <translation>Una zona es de exclusión o de inclusión, no «%1».</translation>
    </message>
    <message>
        <source>Zone kind</source>
        <translation>Clase de zona</translation>
    </message>
    <message>
        <source>Heights are AMSL, AGL or HOME, not &quot;%1&quot;.</source>
        <translation>Las alturas son AMSL, AGL o HOME, no «%1».</translation>
    </message>
    <message>
        <source>A floor or ceiling is a number of metres, or empty.</source>
        <translation>Una base o un techo es un número de metros, o vacío.</translation>
    </message>
    <message>
        <source>The ceiling (%1 m) must be above the floor (%2 m).</source>
        <translation>El techo (%1 m) debe estar por encima de la base (%2 m).</translation>
    </message>
    <message>
        <source>Zone floor and ceiling</source>
        <translation>Base y techo de zona</translation>
    </message>
    <message>
        <source>The zone would not be a valid polygon: %1</source>
        <translation>La zona no sería un polígono válido: %1</translation>
    </message>
    <message>
        <source>Zone %1</source>
        <translation>Zona %1</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneFeed</name>
    <message>
        <source>Another zone feed is being fetched.</source>
        <translation>Se está descargando otro feed de zonas.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no web address (http:// or https://).</source>
        <translation>«%1» no es una dirección web (http:// o https://).</translation>
    </message>
    <message>
        <source>There is no folder to keep the zone feed in (%1).</source>
        <translation>No hay carpeta donde guardar el feed de zonas (%1).</translation>
    </message>
    <message>
        <source>The zone feed is larger than %1 MiB; it was not kept.</source>
        <translation>El feed de zonas ocupa más de %1 MiB; no se ha guardado.</translation>
    </message>
    <message>
        <source>The zone feed&apos;s fetch was stopped (cancelled, or no answer for %1 s).</source>
        <translation>La descarga del feed de zonas se detuvo (cancelada, o sin respuesta durante %1 s).</translation>
    </message>
    <message>
        <source>The zone feed&apos;s server answered HTTP %1.</source>
        <translation>El servidor del feed de zonas respondió HTTP %1.</translation>
    </message>
    <message>
        <source>The zone feed cannot be fetched: %1.</source>
        <translation>No se puede descargar el feed de zonas: %1.</translation>
    </message>
    <message>
        <source>The zone feed&apos;s server sent nothing.</source>
        <translation>El servidor del feed de zonas no envió nada.</translation>
    </message>
    <message>
        <source>The zone feed cannot be kept in %1: %2.</source>
        <translation>No se puede guardar el feed de zonas en %1: %2.</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneSharing</name>
    <message>
        <source>Wait: the server has not answered the last change yet.</source>
        <translation>Espere: el servidor aún no ha respondido al último cambio.</translation>
    </message>
    <message>
        <source>Only a zone drawn here can be sent to the server.</source>
        <translation>Solo se puede enviar al servidor una zona dibujada aquí.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was changed on the server since you copied it (version %2, now %3). Remove your copy and edit the server&apos;s zone again.</source>
        <translation>La zona «%1» se modificó en el servidor desde que usted la copió (versión %2, ahora %3). Quite su copia y vuelva a editar la zona del servidor.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; is on the server; you changed it since sending, so your copy stays.</source>
        <translation>La zona «%1» está en el servidor; usted la modificó después de enviarla, así que su copia se conserva.</translation>
    </message>
    <message>
        <source>Send zone &apos;%1&apos; to the server</source>
        <translation>Enviar la zona «%1» al servidor</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; is on the server.</source>
        <translation>La zona «%1» está en el servidor.</translation>
    </message>
    <message>
        <source>Only the server&apos;s custom zones can be edited here; aerodrome zones are the server&apos;s own.</source>
        <translation>Aquí solo se pueden editar las zonas personalizadas del servidor; las zonas de aeródromo son del propio servidor.</translation>
    </message>
    <message>
        <source>Edit server zone &apos;%1&apos;</source>
        <translation>Editar la zona del servidor «%1»</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; is drawn here to edit; send it to store the change on the server.</source>
        <translation>La zona «%1» está dibujada aquí para editarla; envíela para guardar el cambio en el servidor.</translation>
    </message>
    <message>
        <source>Only the server&apos;s custom zones can be deleted here.</source>
        <translation>Aquí solo se pueden eliminar las zonas personalizadas del servidor.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was deleted on the server.</source>
        <translation>La zona «%1» se eliminó en el servidor.</translation>
    </message>
</context>
<context>
    <name>sortie::client::AutosaveRecovery</name>
    <message>
        <source>The autosaved edits in %1 cannot be read: %2</source>
        <translation>No se pueden leer las ediciones guardadas automáticamente en %1: %2</translation>
    </message>
    <message>
        <source>The autosaved edits in %1 cannot be read (%2). The file was kept as %3.</source>
        <translation>No se pueden leer las ediciones guardadas automáticamente en %1 (%2). El archivo se conservó como %3.</translation>
    </message>
    <message>
        <source>The autosaved edits in %1 cannot be read (%2).</source>
        <translation>No se pueden leer las ediciones guardadas automáticamente en %1 (%2).</translation>
    </message>
    <message>
        <source>Untitled route</source>
        <translation>Ruta sin título</translation>
    </message>
    <message>
        <source>route %1, version %2</source>
        <translation>ruta %1, versión %2</translation>
    </message>
    <message>
        <source>, on %1</source>
        <translation>, en %1</translation>
    </message>
    <message>
        <source> as %1</source>
        <translation> como %1</translation>
    </message>
    <message>
        <source>The route open now has unsaved edits, and restoring would replace it: save or undo them first.</source>
        <translation>La ruta abierta tiene ediciones sin guardar y restaurar la reemplazaría: guárdelas o deshágalas primero.</translation>
    </message>
    <message>
        <source>%1 as %2</source>
        <translation>%1 como %2</translation>
    </message>
    <message>
        <source>These edits belong to route %1 on %2, and saving them updates that route. Sign in to %2 to restore them: choose Later, sign in, and they are offered again.</source>
        <translation>Estas ediciones pertenecen a la ruta %1 en %2, y guardarlas actualiza esa ruta. Inicie sesión en %2 para restaurarlas: elija Más tarde, inicie sesión y se le ofrecerán de nuevo.</translation>
    </message>
    <message>
        <source>These edits belong to route %1 on %2, but this session is signed in to %3 as %4. Sign out and sign in to %2 to restore them; until then they are kept and offered again at each start.</source>
        <translation>Estas ediciones pertenecen a la ruta %1 en %2, pero esta sesión está iniciada en %3 como %4. Cierre la sesión e inicie sesión en %2 para restaurarlas; hasta entonces se conservan y se ofrecen de nuevo en cada inicio.</translation>
    </message>
    <message>
        <source>Restore autosaved edits</source>
        <translation>Restaurar ediciones guardadas automáticamente</translation>
    </message>
    <message>
        <source>The autosave %1 could not be moved aside.</source>
        <translation>No se pudo apartar el guardado automático %1.</translation>
    </message>
</context>
<context>
    <name>sortie::client::CommandPolicy</name>
    <message>
        <source>Manual</source>
        <translation>Manual</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Espera</translation>
    </message>
    <message>
        <source>Taking off</source>
        <translation>Despegando</translation>
    </message>
    <message>
        <source>Auto (fly the mission)</source>
        <translation>Auto (volar la misión)</translation>
    </message>
    <message>
        <source>Guided</source>
        <translation>Guiado</translation>
    </message>
    <message>
        <source>Land</source>
        <translation>Aterrizaje</translation>
    </message>
    <message>
        <source>Return home</source>
        <translation>Vuelta al origen</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Desconocido</translation>
    </message>
    <message>
        <source>the vehicle</source>
        <translation>el vehículo</translation>
    </message>
    <message>
        <source>Arm %1? Its motors may start.</source>
        <translation>¿Armar %1? Sus motores pueden arrancar.</translation>
    </message>
    <message>
        <source>Disarm %1? It may be in the air, and would fall.</source>
        <translation>¿Desarmar %1? Puede estar en el aire, y caería.</translation>
    </message>
    <message>
        <source>Take off with %1 to %2 m above home?</source>
        <translation>¿Despegar con %1 hasta %2 m sobre el origen?</translation>
    </message>
    <message numerus="yes">
        <source>Start the mission on %1 (%n waypoint(s))?</source>
        <translation>
            <numerusform>¿Iniciar la misión en %1 (%n waypoint)?</numerusform>
            <numerusform>¿Iniciar la misión en %1 (%n waypoints)?</numerusform>
        </translation>
    </message>
    <message>
        <source>Start the mission on %1? Sortie has not seen its mission.</source>
        <translation>¿Iniciar la misión en %1? Sortie no ha visto su misión.</translation>
    </message>
    <message>
        <source>Arm</source>
        <translation>Armar</translation>
    </message>
    <message>
        <source>Disarm</source>
        <translation>Desarmar</translation>
    </message>
    <message>
        <source>Take off</source>
        <translation>Despegar</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <source>%1 sent despite the checklist (the operator overrode it): %2</source>
        <translation>%1 enviado pese a la lista de comprobación (el operador la anuló): %2</translation>
    </message>
</context>
<context>
    <name>sortie::client::ConnectionController</name>
    <message>
        <source>connection lost; attempt %1 in %2 s</source>
        <translation>conexión perdida; intento %1 en %2 s</translation>
    </message>
    <message>
        <source>reconnected in a new session</source>
        <translation>reconectado en una nueva sesión</translation>
    </message>
    <message>
        <source>%1 at %2</source>
        <translation>%1 en %2</translation>
    </message>
    <message>
        <source>The server address is not usable: %1.</source>
        <translation>La dirección del servidor no es utilizable: %1.</translation>
    </message>
    <message>
        <source>Enter a user name.</source>
        <translation>Introduzca un nombre de usuario.</translation>
    </message>
    <message>
        <source>%1. Check the server&apos;s address and this computer&apos;s network.</source>
        <translation>%1. Compruebe la dirección del servidor y la red de este equipo.</translation>
    </message>
    <message>
        <source>%1. Is the UgCS server running, and is the port right?</source>
        <translation>%1. ¿Está en marcha el servidor UgCS y es correcto el puerto?</translation>
    </message>
    <message>
        <source>Wrong user name or password (%1).</source>
        <translation>Nombre de usuario o contraseña incorrectos (%1).</translation>
    </message>
    <message>
        <source>%1. This server cannot be used with Sortie.</source>
        <translation>%1. Este servidor no se puede usar con Sortie.</translation>
    </message>
    <message>
        <source>The server&apos;s licence allows no more connections (%1). Close another client or extend the licence.</source>
        <translation>La licencia del servidor no admite más conexiones (%1). Cierre otro cliente o amplíe la licencia.</translation>
    </message>
    <message>
        <source>The server did not answer in time (%1). It may be overloaded or not a UgCS server.</source>
        <translation>El servidor no respondió a tiempo (%1). Puede estar sobrecargado o no ser un servidor UgCS.</translation>
    </message>
    <message>
        <source>The connection was closed (%1).</source>
        <translation>Se cerró la conexión (%1).</translation>
    </message>
    <message>
        <source>The server answered something Sortie cannot use (%1).</source>
        <translation>El servidor respondió algo que Sortie no puede usar (%1).</translation>
    </message>
    <message>
        <source>The server refused: %1</source>
        <translation>El servidor se negó: %1</translation>
    </message>
    <message>
        <source>Disconnected</source>
        <translation>Desconectado</translation>
    </message>
    <message>
        <source>Connecting</source>
        <translation>Conectando</translation>
    </message>
    <message>
        <source>Authorizing</source>
        <translation>Autorizando</translation>
    </message>
    <message>
        <source>Logging in</source>
        <translation>Iniciando sesión</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Listo</translation>
    </message>
    <message>
        <source>Reconnecting</source>
        <translation>Reconectando</translation>
    </message>
    <message>
        <source>%1 is not this computer, and this connection is not secured: the password for %2 would cross the network in clear, readable by anyone on the way, at every login and reconnect. Send it in clear to this server? (Choose Secure if the server is behind a TLS terminator.)</source>
        <translation>%1 no es este ordenador y esta conexión no está protegida: la contraseña de %2 cruzaría la red sin cifrar, legible para cualquiera en el camino, en cada inicio de sesión y reconexión. ¿Enviarla sin cifrar a este servidor? (Elija «Segura» si el servidor está detrás de un terminador TLS).</translation>
    </message>
    <message>
        <source>Not connected to %1: the password was not sent.</source>
        <translation>Sin conexión con %1: la contraseña no se envió.</translation>
    </message>
    <message>
        <source>First secure connection to %1: its certificate is now trusted for this server and remembered. Compare its SHA-256 fingerprint with the server&apos;s: %2</source>
        <translation>Primera conexión segura con %1: su certificado es ahora de confianza para este servidor y queda recordado. Compare su huella SHA-256 con la del servidor: %2</translation>
    </message>
    <message>
        <source>Secured by TLS: the certificate remembered for %1 (SHA-256 %2).</source>
        <translation>Protegida por TLS: el certificado recordado para %1 (SHA-256 %2).</translation>
    </message>
    <message>
        <source>Secured by TLS: the certificate pinned for %1 (SHA-256 %2).</source>
        <translation>Protegida por TLS: el certificado fijado para %1 (SHA-256 %2).</translation>
    </message>
    <message>
        <source>Secured by TLS: a certificate this computer trusts (SHA-256 %1).</source>
        <translation>Protegida por TLS: un certificado en el que confía este ordenador (SHA-256 %1).</translation>
    </message>
    <message>
        <source>%1. The password was not sent.</source>
        <translation>%1. La contraseña no se envió.</translation>
    </message>
</context>
<context>
    <name>sortie::client::FleetRoutes</name>
    <message>
        <source>Unnamed route</source>
        <translation>Ruta sin nombre</translation>
    </message>
    <message>
        <source>planned</source>
        <translation>planificada</translation>
    </message>
    <message>
        <source>uploaded %1</source>
        <translation>subida %1</translation>
    </message>
    <message>
        <source>paused: waypoint %1 of %2</source>
        <translation>en pausa: waypoint %1 de %2</translation>
    </message>
    <message>
        <source>flying: waypoint %1 of %2</source>
        <translation>en vuelo: waypoint %1 de %2</translation>
    </message>
    <message>
        <source>flown</source>
        <translation>volada</translation>
    </message>
</context>
<context>
    <name>sortie::client::MissionController</name>
    <message>
        <source>Reading the server&apos;s routes</source>
        <translation>Leyendo las rutas del servidor</translation>
    </message>
    <message>
        <source>The server&apos;s routes could not be read: %1</source>
        <translation>No se pudieron leer las rutas del servidor: %1</translation>
    </message>
    <message numerus="yes">
        <source>%1%n segment(s)</source>
        <translation>
            <numerusform>%1%n segmento</numerusform>
            <numerusform>%1%n segmentos</numerusform>
        </translation>
    </message>
    <message>
        <source>Reading the server&apos;s vehicles</source>
        <translation>Leyendo los vehículos del servidor</translation>
    </message>
    <message>
        <source>Opening the route</source>
        <translation>Abriendo la ruta</translation>
    </message>
    <message>
        <source>The route could not be opened: %1</source>
        <translation>No se pudo abrir la ruta: %1</translation>
    </message>
    <message>
        <source>The route cannot be edited here: %1</source>
        <translation>La ruta no se puede editar aquí: %1</translation>
    </message>
    <message>
        <source>Opened %1 (version %2).</source>
        <translation>Abierta %1 (versión %2).</translation>
    </message>
    <message>
        <source>Not connected: your edits are kept; save again when the connection is back.</source>
        <translation>Sin conexión: sus ediciones se conservan; guarde de nuevo cuando vuelva la conexión.</translation>
    </message>
    <message>
        <source>Wait until %1 is done.</source>
        <translation>Espere a que termine la operación en curso (%1).</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>No guardado: %1</translation>
    </message>
    <message>
        <source>Saving</source>
        <translation>Guardando</translation>
    </message>
    <message>
        <source>Locking the route</source>
        <translation>Bloqueando la ruta</translation>
    </message>
    <message>
        <source>Not saved: the route is locked (%1).</source>
        <translation>No guardado: la ruta está bloqueada (%1).</translation>
    </message>
    <message>
        <source>Reading the server&apos;s copy</source>
        <translation>Leyendo la copia del servidor</translation>
    </message>
    <message>
        <source>Someone else saved this route on the server (version %1) after you opened it (version %2).</source>
        <translation>Otra persona guardó esta ruta en el servidor (versión %1) después de que usted la abriera (versión %2).</translation>
    </message>
    <message>
        <source>Saved, but the server&apos;s answer cannot be read back: %1</source>
        <translation>Guardado, pero no se puede leer la respuesta del servidor: %1</translation>
    </message>
    <message>
        <source>Saved %1 (version %2).</source>
        <translation>Guardada %1 (versión %2).</translation>
    </message>
    <message>
        <source>Take the server&apos;s version</source>
        <translation>Tomar la versión del servidor</translation>
    </message>
    <message>
        <source>This is the server&apos;s copy now. Undo brings your edits back.</source>
        <translation>Ahora esta es la copia del servidor. Deshacer recupera sus ediciones.</translation>
    </message>
    <message>
        <source>This route was deleted on the server. Your copy stays open.</source>
        <translation>Esta ruta se eliminó en el servidor. Su copia sigue abierta.</translation>
    </message>
    <message>
        <source>Updated from the server (version %1).</source>
        <translation>Actualizada desde el servidor (versión %1).</translation>
    </message>
    <message>
        <source>Someone else saved this route on the server (version %1) while you were editing it.</source>
        <translation>Otra persona guardó esta ruta en el servidor (versión %1) mientras usted la editaba.</translation>
    </message>
    <message>
        <source>The new route</source>
        <translation>La ruta nueva</translation>
    </message>
    <message>
        <source>&quot;%1&quot;</source>
        <translation>«%1»</translation>
    </message>
    <message>
        <source>%1 has unsaved edits. Opening it again reads the server&apos;s copy. Save your edits first?</source>
        <translation>%1 tiene cambios sin guardar. Abrirla de nuevo lee la copia del servidor. ¿Guardar primero los cambios?</translation>
    </message>
    <message>
        <source>%1 has unsaved edits. Save them before opening &quot;%2&quot;?</source>
        <translation>%1 tiene cambios sin guardar. ¿Guardarlos antes de abrir «%2»?</translation>
    </message>
    <message>
        <source>If you discard them, Undo brings them back.</source>
        <translation>Si los descarta, Deshacer los recupera.</translation>
    </message>
    <message>
        <source>the new route</source>
        <translation>la ruta nueva</translation>
    </message>
    <message>
        <source>Open %1</source>
        <translation>Abrir %1</translation>
    </message>
    <message>
        <source>Undo brings back your unsaved edits of %1.</source>
        <translation>Deshacer recupera sus cambios sin guardar de %1.</translation>
    </message>
    <message>
        <source>Not saved: another route was opened meanwhile.</source>
        <translation>No guardado: mientras tanto se abrió otra ruta.</translation>
    </message>
    <message>
        <source>Edits made while saving</source>
        <translation>Cambios hechos durante el guardado</translation>
    </message>
    <message>
        <source>The edits you made while it was saving are kept, not saved yet.</source>
        <translation>Los cambios que hizo mientras se guardaba se conservan, aún sin guardar.</translation>
    </message>
    <message>
        <source>Update from the server (version %1)</source>
        <translation>Actualización del servidor (versión %1)</translation>
    </message>
</context>
<context>
    <name>sortie::client::MissionUploader</name>
    <message>
        <source>Checking the route</source>
        <translation>Comprobando la ruta</translation>
    </message>
    <message>
        <source>Waiting for your answer</source>
        <translation>Esperando su respuesta</translation>
    </message>
    <message>
        <source>Processing for %1</source>
        <translation>Procesando para %1</translation>
    </message>
    <message>
        <source>Taking control of %1</source>
        <translation>Tomando el control de %1</translation>
    </message>
    <message>
        <source>Uploading to %1</source>
        <translation>Subiendo a %1</translation>
    </message>
    <message>
        <source>Releasing %1</source>
        <translation>Liberando %1</translation>
    </message>
    <message>
        <source>Reading the mission back from %1</source>
        <translation>Leyendo de nuevo la misión desde %1</translation>
    </message>
    <message>
        <source>upload &quot;%1&quot;</source>
        <translation>subir «%1»</translation>
    </message>
    <message>
        <source>route</source>
        <translation>ruta</translation>
    </message>
    <message>
        <source>Upload to %1 failed: the vehicle is gone (its connection was closed).</source>
        <translation>Falló la subida a %1: el vehículo ya no está (se cerró su conexión).</translation>
    </message>
    <message>
        <source>the vehicle is gone</source>
        <translation>el vehículo ya no está</translation>
    </message>
    <message>
        <source>Not uploaded: %1</source>
        <translation>No subida: %1</translation>
    </message>
    <message>
        <source>Too late to cancel: the mission is being sent to %1.</source>
        <translation>Demasiado tarde para cancelar: la misión se está enviando a %1.</translation>
    </message>
    <message>
        <source>Upload to %1 cancelled; nothing was sent.</source>
        <translation>Subida a %1 cancelada; no se envió nada.</translation>
    </message>
    <message>
        <source>Upload to %1 failed: the vehicle has no link.</source>
        <translation>Falló la subida a %1: el vehículo no tiene enlace.</translation>
    </message>
    <message>
        <source>no link</source>
        <translation>sin enlace</translation>
    </message>
    <message>
        <source>Not uploaded to %1: %2</source>
        <translation>No subida a %1: %2</translation>
    </message>
    <message>
        <source>the route&apos;s fence is not sent: %1 keeps no fence (HCI)</source>
        <translation>no se envía la geocerca de la ruta: %1 no guarda geocerca (HCI)</translation>
    </message>
    <message>
        <source>Upload to %1 failed: %2</source>
        <translation>Falló la subida a %1: %2</translation>
    </message>
    <message>
        <source>Uploaded to %1, but it could not be read back: %2</source>
        <translation>Subida a %1, pero no se pudo leer de vuelta: %2</translation>
    </message>
    <message>
        <source>Uploaded to %1, but it holds something else: %2</source>
        <translation>Subida a %1, pero contiene otra cosa: %2</translation>
    </message>
    <message numerus="yes">
        <source>Uploaded to %1: %n waypoint(s).</source>
        <translation>
            <numerusform>Subida a %1: %n waypoint.</numerusform>
            <numerusform>Subida a %1: %n waypoints.</numerusform>
        </translation>
    </message>
    <message>
        <source>Note: %1</source>
        <translation>Nota: %1</translation>
    </message>
</context>
<context>
    <name>sortie::client::RouteAutosave</name>
    <message>
        <source>No free autosave slot in %1: edits are not autosaved.</source>
        <translation>No hay ninguna ranura libre de guardado automático en %1: las ediciones no se guardan automáticamente.</translation>
    </message>
</context>
<context>
    <name>sortie::client::RouteDocument</name>
    <message>
        <source>Import failed: %1</source>
        <translation>Falló la importación: %1</translation>
    </message>
    <message>
        <source>Import failed: %1 holds no route.</source>
        <translation>Falló la importación: %1 no contiene ninguna ruta.</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importar %1</translation>
    </message>
    <message numerus="yes">
        <source>Imported %n segment(s) from %1.</source>
        <translation>
            <numerusform>Importado %n segmento de %1.</numerusform>
            <numerusform>Importados %n segmentos de %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>The file holds %1 routes; this is the first (&quot;%2&quot;).</source>
        <translation>El archivo contiene %1 rutas; esta es la primera («%2»).</translation>
    </message>
    <message>
        <source>Export failed: %1</source>
        <translation>Falló la exportación: %1</translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation>Exportado a %1.</translation>
    </message>
    <message>
        <source>Not representable there: %1</source>
        <translation>No representable allí: %1</translation>
    </message>
</context>
<context>
    <name>sortie::client::RoutePreparation</name>
    <message>
        <source>Choose the vehicle to %1 for.</source>
        <translation>Elija el vehículo para el que %1.</translation>
    </message>
    <message>
        <source>process the route</source>
        <translation>procesar la ruta</translation>
    </message>
    <message>
        <source>%1 has no link.</source>
        <translation>%1 no tiene enlace.</translation>
    </message>
    <message>
        <source>Processing for %1…</source>
        <translation>Procesando para %1…</translation>
    </message>
    <message>
        <source>Not processed for %1: %2</source>
        <translation>No procesada para %1: %2</translation>
    </message>
    <message numerus="yes">
        <source>Processed for %1: %n waypoint(s) to fly.</source>
        <translation>
            <numerusform>Procesada para %1: %n waypoint que volar.</numerusform>
            <numerusform>Procesada para %1: %n waypoints que volar.</numerusform>
        </translation>
    </message>
    <message>
        <source>upload</source>
        <translation>subir</translation>
    </message>
    <message>
        <source>An upload is waiting for your answer.</source>
        <translation>Una subida espera su respuesta.</translation>
    </message>
    <message>
        <source>Wait until %1 is done.</source>
        <translation>Espere a que termine la operación en curso (%1).</translation>
    </message>
</context>
<context>
    <name>sortie::client::VehicleFleet</name>
    <message>
        <source>%1: %2 done.</source>
        <translation>%1: %2 completado.</translation>
    </message>
    <message>
        <source>%1: %2 failed: %3</source>
        <translation>%1: falló %2: %3</translation>
    </message>
    <message>
        <source>The server&apos;s vehicles could not be read: %1</source>
        <translation>No se pudieron leer los vehículos del servidor: %1</translation>
    </message>
    <message>
        <source>Not a VCI address: %1</source>
        <translation>No es una dirección VCI: %1</translation>
    </message>
    <message>
        <source>go to %1, %2 at %3 m</source>
        <translation>ir a %1, %2 a %3 m</translation>
    </message>
    <message>
        <source>%1: flying to the clicked point.</source>
        <translation>%1: volando al punto pulsado.</translation>
    </message>
    <message>
        <source>%1: go-to failed: %2</source>
        <translation>%1: falló el ir a: %2</translation>
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
            <numerusform>%1 (%n waypoint)</numerusform>
            <numerusform>%1 (%n waypoints)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Arm %n vehicle(s): %1? Their motors may start.</source>
        <translation>
            <numerusform>¿Armar %n vehículo: %1? Sus motores pueden arrancar.</numerusform>
            <numerusform>¿Armar %n vehículos: %1? Sus motores pueden arrancar.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Disarm %n vehicle(s): %1? One in the air would fall.</source>
        <translation>
            <numerusform>¿Desarmar %n vehículo: %1? Si está en el aire, caería.</numerusform>
            <numerusform>¿Desarmar %n vehículos: %1? Uno que esté en el aire caería.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Take off with %n vehicle(s) to their altitudes above home: %1?</source>
        <translation>
            <numerusform>¿Despegar con %n vehículo hasta su altitud sobre el origen: %1?</numerusform>
            <numerusform>¿Despegar con %n vehículos hasta sus altitudes sobre el origen: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Start or resume the mission on %n vehicle(s): %1?</source>
        <translation>
            <numerusform>¿Iniciar o reanudar la misión en %n vehículo: %1?</numerusform>
            <numerusform>¿Iniciar o reanudar la misión en %n vehículos: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Pause %n vehicle(s) where they are: %1?</source>
        <translation>
            <numerusform>¿Pausar %n vehículo donde está: %1?</numerusform>
            <numerusform>¿Pausar %n vehículos donde están: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Land %n vehicle(s) where they are: %1?</source>
        <translation>
            <numerusform>¿Aterrizar %n vehículo donde está: %1?</numerusform>
            <numerusform>¿Aterrizar %n vehículos donde están: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Send %n vehicle(s) home: %1?</source>
        <translation>
            <numerusform>¿Enviar %n vehículo al origen: %1?</numerusform>
            <numerusform>¿Enviar %n vehículos al origen: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Switch %n vehicle(s) to %2: %1?</source>
        <translation>
            <numerusform>¿Cambiar %n vehículo a %2: %1?</numerusform>
            <numerusform>¿Cambiar %n vehículos a %2: %1?</numerusform>
        </translation>
    </message>
    <message>
        <source>not sent</source>
        <translation>no enviado</translation>
    </message>
    <message>
        <source>%1 waiting</source>
        <translation>%1 en espera</translation>
    </message>
    <message>
        <source>%1 done</source>
        <translation>%1 completado</translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation>%1 falló: %2</translation>
    </message>
    <message numerus="yes">
        <source>%1: %2 of %n vehicle(s) answered — %3.</source>
        <translation>
            <numerusform>%1: respondió %2 de %n vehículo — %3.</numerusform>
            <numerusform>%1: respondieron %2 de %n vehículos — %3.</numerusform>
        </translation>
    </message>
    <message>
        <source>Held back by their checklist, not sent: %1.</source>
        <translation>Retenidos por su lista de comprobación, no enviados: %1.</translation>
    </message>
    <message>
        <source>held back by its checklist (%1)</source>
        <translation>retenido por su lista de comprobación (%1)</translation>
    </message>
</context>
<context>
    <name>sortie::coverage::PhotoSurvey</name>
    <message>
        <source>Choose the vehicle that took the photos.</source>
        <translation>Elija el vehículo que tomó las fotos.</translation>
    </message>
    <message>
        <source>choose the camera that took them</source>
        <translation>elija la cámara que las tomó</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>no medido</translation>
    </message>
    <message>
        <source>Open the flight&apos;s log first.</source>
        <translation>Abra primero el registro del vuelo.</translation>
    </message>
    <message>
        <source>Choose the folder of the flight&apos;s photos.</source>
        <translation>Elija la carpeta de las fotos del vuelo.</translation>
    </message>
    <message>
        <source>No photo is placed: nothing to write.</source>
        <translation>Ninguna foto está situada: nada que escribir.</translation>
    </message>
    <message>
        <source>%1 is the photos&apos; own folder: the copies go elsewhere, the originals are never changed.</source>
        <translation>%1 es la carpeta de las propias fotos: las copias van a otro sitio, los originales nunca se cambian.</translation>
    </message>
    <message>
        <source>%1: the folder cannot be made.</source>
        <translation>%1: no se puede crear la carpeta.</translation>
    </message>
    <message numerus="yes">
        <source>%n geotagged copies, geo.txt and geotags.csv written to %1.</source>
        <translation>
            <numerusform>%n copia georreferenciada, geo.txt y geotags.csv escritos en %1.</numerusform>
            <numerusform>%n copias georreferenciadas, geo.txt y geotags.csv escritos en %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 not written: %2.</source>
        <translation>%1 no escrita: %2.</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n photos placed on %2&apos;s track (camera clock %3 s).</source>
        <translation>
            <numerusform>%1 de %n foto situada en la traza de %2 (reloj de la cámara %3 s).</numerusform>
            <numerusform>%1 de %n fotos situadas en la traza de %2 (reloj de la cámara %3 s).</numerusform>
        </translation>
    </message>
    <message>
        <source>Coverage not judged: %1.</source>
        <translation>Cobertura no evaluada: %1.</translation>
    </message>
    <message numerus="yes">
        <source>%1 % of %2 m² seen by at least %3 images; forward overlap %4, side %5; %6 per pixel; %n hole(s).</source>
        <translation>
            <numerusform>%1 % de %2 m² visto por al menos %3 imágenes; solape frontal %4, lateral %5; %6 por píxel; %n hueco.</numerusform>
            <numerusform>%1 % de %2 m² visto por al menos %3 imágenes; solape frontal %4, lateral %5; %6 por píxel; %n huecos.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 m² at %2, %3</source>
        <translation>%1 m² en %2, %3</translation>
    </message>
    <message>
        <source>No hole could be planned as an area scan: %1</source>
        <translation>Ningún hueco se pudo planificar como barrido de área: %1</translation>
    </message>
    <message>
        <source>Re-fly the gaps</source>
        <translation>Volver a volar los huecos</translation>
    </message>
    <message numerus="yes">
        <source>&quot;Re-fly the gaps&quot; is open in the mission editor: %n area scan(s) at %1 m, %2/%3 % overlap.</source>
        <translation>
            <numerusform>«Volver a volar los huecos» está abierta en el editor de misiones: %n barrido de área a %1 m, solape %2/%3 %.</numerusform>
            <numerusform>«Volver a volar los huecos» está abierta en el editor de misiones: %n barridos de área a %1 m, solape %2/%3 %.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n photos placed where %2 took them, paired with its photo events (camera clock %3 s off).</source>
        <translation>
            <numerusform>%1 de %n foto colocada donde %2 la tomó, emparejada con sus eventos de foto (reloj de la cámara desfasado %3 s).</numerusform>
            <numerusform>%1 de %n fotos colocadas donde %2 las tomó, emparejadas con sus eventos de foto (reloj de la cámara desfasado %3 s).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n photo(s) the vehicle took are not in the folder.</source>
        <translation>
            <numerusform>%n foto que tomó el vehículo no está en la carpeta.</numerusform>
            <numerusform>%n fotos que tomó el vehículo no están en la carpeta.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::deconfliction::FleetConflictRule</name>
    <message>
        <source>%1, flying &quot;%2&quot; (its leg %3)</source>
        <translation>%1, volando «%2» (su tramo %3)</translation>
    </message>
    <message>
        <source>%1&apos;s uploaded &quot;%2&quot; (its leg %3) if it starts now</source>
        <translation>la ruta «%2» subida a %1 (su tramo %3) si empieza ahora</translation>
    </message>
    <message>
        <source>Leg %1 comes within %2 m across and %3 m in height of %4, %5 after the start%6.</source>
        <translation>El tramo %1 pasa a menos de %2 m en horizontal y %3 m en altura de %4, %5 después del inicio%6.</translation>
    </message>
    <message>
        <source> (heights in different frames: judged across only)</source>
        <translation> (alturas en referencias distintas: solo se juzga en horizontal)</translation>
    </message>
</context>
<context>
    <name>sortie::deconfliction::ProximityMonitor</name>
    <message>
        <source>now</source>
        <translation>ahora</translation>
    </message>
    <message>
        <source>in %1 s</source>
        <translation>en %1 s</translation>
    </message>
    <message>
        <source>%1 and traffic %2: closest %3, %4 across and %5 in height</source>
        <translation>%1 y el tráfico %2: máxima aproximación %3, %4 en horizontal y %5 en altura</translation>
    </message>
    <message>
        <source>%1 and %2: closest %3, %4 across and %5 in height</source>
        <translation>%1 y %2: máxima aproximación %3, %4 en horizontal y %5 en altura</translation>
    </message>
</context>
<context>
    <name>sortie::endurance::EnduranceAdvisory</name>
    <message>
        <source>No vehicle chosen</source>
        <translation>Ningún vehículo elegido</translation>
    </message>
    <message>
        <source>No energy profile: choose the vehicle&apos;s profile file on the mission page</source>
        <translation>Sin perfil energético: elija el archivo de perfil del vehículo en la página de misión</translation>
    </message>
    <message>
        <source>The vehicle reports no remaining battery</source>
        <translation>El vehículo no informa de la batería restante</translation>
    </message>
    <message>
        <source>The vehicle reports no home</source>
        <translation>El vehículo no informa de su origen</translation>
    </message>
    <message>
        <source>The vehicle reports no position</source>
        <translation>El vehículo no informa de su posición</translation>
    </message>
    <message>
        <source>No mission on board</source>
        <translation>No hay misión a bordo</translation>
    </message>
    <message>
        <source>The vehicle cannot make headway home against the wind</source>
        <translation>El vehículo no puede avanzar hacia el origen contra el viento</translation>
    </message>
    <message>
        <source>Battery at end of route: %1 · home needs %2</source>
        <translation>Batería al final de la ruta: %1 · el regreso necesita %2</translation>
    </message>
    <message>
        <source>Battery: time to come home — no headway home against the wind</source>
        <translation>Batería: hora de volver — sin avance hacia el origen contra el viento</translation>
    </message>
    <message>
        <source>Battery: time to come home — %1 left, home needs %2: the %3 reserve is being used</source>
        <translation>Batería: hora de volver — quedan %1, el regreso necesita %2: se está usando la reserva de %3</translation>
    </message>
    <message>
        <source>Battery: time to come home — %1 left, home needs %2 and the reserve %3: %4 to spare</source>
        <translation>Batería: hora de volver — quedan %1, el regreso necesita %2 y la reserva %3: sobran %4</translation>
    </message>
    <message>
        <source>Return %1 home now? %2</source>
        <translation>¿Enviar %1 al origen ahora? %2</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ComparisonController</name>
    <message>
        <source>Open a flight log first.</source>
        <translation>Abra primero un registro de vuelo.</translation>
    </message>
    <message>
        <source>%1 holds no route.</source>
        <translation>%1 no contiene ninguna ruta.</translation>
    </message>
    <message>
        <source>Choose the vehicle to compare on the map or in the list.</source>
        <translation>Elija el vehículo que comparar en el mapa o en la lista.</translation>
    </message>
    <message>
        <source>%1 on &quot;%2&quot;: %3 of %4 waypoints reached; cross-track max %5 m, mean %6 m; altitude max %7 m</source>
        <translation>%1 en «%2»: %3 de %4 waypoints alcanzados; desvío lateral máx. %5 m, media %6 m; altitud máx. %7 m</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::FlightLogWriter</name>
    <message>
        <source>%1: the log cannot use a write-ahead journal</source>
        <translation>%1: el registro no puede usar un diario de escritura anticipada</translation>
    </message>
    <message>
        <source>Recording could not continue in %1: %2</source>
        <translation>La grabación no pudo continuar en %1: %2</translation>
    </message>
    <message>
        <source>%1 is being written by another process</source>
        <translation>otro proceso está escribiendo %1</translation>
    </message>
    <message>
        <source>Recording to %1 failed: %2. What is recorded meanwhile is kept and written once it can be.</source>
        <translation>La grabación en %1 falló: %2. Lo grabado mientras tanto se conserva y se escribe en cuanto se pueda.</translation>
    </message>
    <message numerus="yes">
        <source>Recording to %1 resumed; %n value(s) recorded while it failed could not be kept.</source>
        <translation>
            <numerusform>Grabación en %1 reanudada; no se pudo conservar %n valor grabado durante el fallo.</numerusform>
            <numerusform>Grabación en %1 reanudada; no se pudieron conservar %n valores grabados durante el fallo.</numerusform>
        </translation>
    </message>
    <message>
        <source>no row for vehicle %1: %2</source>
        <translation>no hay fila para el vehículo %1: %2</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::FlightRecorder</name>
    <message>
        <source>The flight log %1 cannot be written: %2</source>
        <translation>No se puede escribir el registro de vuelo %1: %2</translation>
    </message>
    <message>
        <source>Recording started</source>
        <translation>Grabación iniciada</translation>
    </message>
    <message>
        <source>Recording stopped</source>
        <translation>Grabación detenida</translation>
    </message>
    <message>
        <source>Route of 1 waypoint</source>
        <translation>Ruta de 1 waypoint</translation>
    </message>
    <message>
        <source>Route of %1 waypoints</source>
        <translation>Ruta de %1 waypoints</translation>
    </message>
    <message>
        <source>Armed</source>
        <translation>Armado</translation>
    </message>
    <message>
        <source>Disarmed</source>
        <translation>Desarmado</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::RecordingSettings</name>
    <message>
        <source>In force: %1; %2.</source>
        <translation>En vigor: %1; %2.</translation>
    </message>
    <message>
        <source>a log up to %1 MB</source>
        <translation>un registro hasta %1 MB</translation>
    </message>
    <message>
        <source>logs of any size</source>
        <translation>registros de cualquier tamaño</translation>
    </message>
    <message>
        <source>the folder up to %1 MB</source>
        <translation>la carpeta hasta %1 MB</translation>
    </message>
    <message>
        <source>the folder without limit</source>
        <translation>la carpeta sin límite</translation>
    </message>
    <message>
        <source>A log&apos;s size must be between 1 and %1 MB, or 0 for no limit.</source>
        <translation>El tamaño de un registro debe estar entre 1 y %1 MB, o 0 para no limitarlo.</translation>
    </message>
    <message>
        <source>The folder&apos;s size must be between 1 and %1 MB, or 0 for no limit.</source>
        <translation>El tamaño de la carpeta debe estar entre 1 y %1 MB, o 0 para no limitarlo.</translation>
    </message>
    <message>
        <source>The folder must hold at least one whole log: make its limit at least a log&apos;s size (%1 MB).</source>
        <translation>La carpeta debe admitir al menos un registro completo: su límite debe ser al menos el tamaño de un registro (%1 MB).</translation>
    </message>
    <message>
        <source>%1 in 1 log</source>
        <translation>%1 en 1 registro</translation>
    </message>
    <message>
        <source>%1 in %2 logs</source>
        <translation>%1 en %2 registros</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ReplayController</name>
    <message>
        <source>%1 of 1 vehicle</source>
        <translation>%1 de 1 vehículo</translation>
    </message>
    <message>
        <source>%1 of %2 vehicles</source>
        <translation>%1 de %2 vehículos</translation>
    </message>
    <message>
        <source>No log is open.</source>
        <translation>No hay ningún registro abierto.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an export format (gpx, kml or csv).</source>
        <translation>«%1» no es un formato de exportación (gpx, kml o csv).</translation>
    </message>
    <message>
        <source>%1 could not be written: %2</source>
        <translation>No se pudo escribir %1: %2</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ServerHistory</name>
    <message>
        <source>not connected to a server</source>
        <translation>sin conexión con un servidor</translation>
    </message>
    <message>
        <source>The server&apos;s history could not be read: %1</source>
        <translation>No se pudo leer el historial del servidor: %1</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ServerHistoryRequest</name>
    <message>
        <source>The server lists no vehicles: connect to a server first.</source>
        <translation>El servidor no muestra ningún vehículo: conéctese primero a un servidor.</translation>
    </message>
    <message>
        <source>Choose a vehicle.</source>
        <translation>Elija un vehículo.</translation>
    </message>
    <message>
        <source>The start &quot;%1&quot; is not a time like %2 (UTC).</source>
        <translation>El inicio «%1» no es una hora con el formato %2 (UTC).</translation>
    </message>
    <message>
        <source>The end &quot;%1&quot; is not a time like %2 (UTC).</source>
        <translation>El fin «%1» no es una hora con el formato %2 (UTC).</translation>
    </message>
    <message>
        <source>The start must be before the end.</source>
        <translation>El inicio debe ser anterior al fin.</translation>
    </message>
    <message>
        <source>The start is in the future.</source>
        <translation>El inicio está en el futuro.</translation>
    </message>
    <message>
        <source>At most 24 hours at a time.</source>
        <translation>Como máximo 24 horas cada vez.</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Cancelado.</translation>
    </message>
    <message>
        <source>The server has no telemetry of %1 from %2 to %3 UTC.</source>
        <translation>El servidor no tiene telemetría de %1 entre %2 y %3 UTC.</translation>
    </message>
    <message>
        <source>There is no replay to show it in.</source>
        <translation>No hay ninguna reproducción en la que mostrarlo.</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ServerRecording</name>
    <message>
        <source>logged in to %1 as %2; recording to %3</source>
        <translation>sesión iniciada en %1 como %2; grabando en %3</translation>
    </message>
    <message>
        <source>server: %1</source>
        <translation>servidor: %1</translation>
    </message>
    <message>
        <source>1 vehicle</source>
        <translation>1 vehículo</translation>
    </message>
    <message>
        <source>%1 vehicles</source>
        <translation>%1 vehículos</translation>
    </message>
    <message>
        <source>log closed: %1</source>
        <translation>registro cerrado: %1</translation>
    </message>
    <message>
        <source>a pinned certificate needs a tls://host:port server and a SHA-256 fingerprint</source>
        <translation>un certificado fijado necesita un servidor tls://host:puerto y una huella SHA-256</translation>
    </message>
    <message>
        <source>%1 is not this computer and the connection is not secured: the password would cross the network in clear. Record over TLS (--server tls://%1), or pass --allow-cleartext to send it in clear.</source>
        <translation>%1 no es este ordenador y la conexión no está protegida: la contraseña cruzaría la red en claro. Grabe por TLS (--server tls://%1) o indique --allow-cleartext para enviarla en claro.</translation>
    </message>
</context>
<context>
    <name>sortie::gamepad::GamepadCommands</name>
    <message>
        <source>Gamepads off</source>
        <translation>Mandos desactivados</translation>
    </message>
    <message>
        <source>Gamepads unavailable: %1</source>
        <translation>Mandos no disponibles: %1</translation>
    </message>
    <message>
        <source>No gamepad attached</source>
        <translation>Ningún mando conectado</translation>
    </message>
</context>
<context>
    <name>sortie::gamepad::GamepadManager</name>
    <message>
        <source>Another gamepad manager already owns SDL in this program.</source>
        <translation>Otro gestor de mandos ya tiene SDL en este programa.</translation>
    </message>
    <message>
        <source>Gamepads are not available: %1</source>
        <translation>Los mandos no están disponibles: %1</translation>
    </message>
</context>
<context>
    <name>sortie::maptiles::OfflineMaps</name>
    <message>
        <source>No route is open.</source>
        <translation>No hay ninguna ruta abierta.</translation>
    </message>
    <message>
        <source>The open route has no waypoints to take the area from.</source>
        <translation>La ruta abierta no tiene waypoints de los que tomar el área.</translation>
    </message>
    <message>
        <source>The route is a single point: give a margin around it.</source>
        <translation>La ruta es un solo punto: indique un margen a su alrededor.</translation>
    </message>
    <message numerus="yes">
        <source>The open route (%n point(s)) and %1 m around it</source>
        <translation>
            <numerusform>La ruta abierta (%n punto) y %1 m alrededor</numerusform>
            <numerusform>La ruta abierta (%n puntos) y %1 m alrededor</numerusform>
        </translation>
    </message>
    <message>
        <source>The map&apos;s view is not an area (%1 to %2).</source>
        <translation>La vista del mapa no es un área (%1 a %2).</translation>
    </message>
    <message>
        <source>The map&apos;s view</source>
        <translation>La vista del mapa</translation>
    </message>
    <message>
        <source>The lowest zoom is above the highest.</source>
        <translation>El zoom mínimo es mayor que el máximo.</translation>
    </message>
    <message>
        <source>Choose an area.</source>
        <translation>Elija un área.</translation>
    </message>
    <message>
        <source>%1 tiles, about %2</source>
        <translation>%1 teselas, unos %2</translation>
    </message>
    <message>
        <source> (at this pack&apos;s mean of %1 a tile)</source>
        <translation> (con la media de este paquete, %1 por tesela)</translation>
    </message>
    <message>
        <source> (assuming %1 a tile)</source>
        <translation> (suponiendo %1 por tesela)</translation>
    </message>
    <message>
        <source>: more than the limit of %1 tiles, choose a smaller area or fewer zoom levels</source>
        <translation>: más que el límite de %1 teselas; elija un área más pequeña o menos niveles de zoom</translation>
    </message>
    <message>
        <source>Choose a web tile server in Map source first: %1</source>
        <translation>Elija primero un servidor de teselas web en Fuente del mapa: %1</translation>
    </message>
    <message>
        <source>%1 of %2 tiles</source>
        <translation>%1 de %2 teselas</translation>
    </message>
    <message>
        <source> · %1 already in the pack</source>
        <translation> · %1 ya en el paquete</translation>
    </message>
    <message>
        <source> · %1 not stored</source>
        <translation> · %1 no guardadas</translation>
    </message>
    <message>
        <source> · paused</source>
        <translation> · en pausa</translation>
    </message>
    <message>
        <source> · done</source>
        <translation> · terminado</translation>
    </message>
    <message>
        <source> · stopped</source>
        <translation> · detenido</translation>
    </message>
    <message>
        <source> · failed</source>
        <translation> · fallido</translation>
    </message>
    <message>
        <source>The drawn area cannot be used: %1</source>
        <translation>El área dibujada no se puede usar: %1</translation>
    </message>
    <message numerus="yes">
        <source>A drawn area (%n corner(s))</source>
        <translation>
            <numerusform>Un área dibujada (%n esquina)</numerusform>
            <numerusform>Un área dibujada (%n esquinas)</numerusform>
        </translation>
    </message>
    <message>
        <source>The drawn rectangle is not an area (%1 to %2).</source>
        <translation>El rectángulo dibujado no es un área (%1 a %2).</translation>
    </message>
    <message>
        <source>A drawn rectangle</source>
        <translation>Un rectángulo dibujado</translation>
    </message>
</context>
<context>
    <name>sortie::maptiles::TilePrefetch</name>
    <message>
        <source>No area is chosen.</source>
        <translation>No se ha elegido ningún área.</translation>
    </message>
    <message>
        <source>The zoom range %1 to %2 is not within 0 to %3.</source>
        <translation>El rango de zoom %1 a %2 no está entre 0 y %3.</translation>
    </message>
    <message>
        <source>The area needs %1 tiles, more than the limit of %2: choose a smaller area or fewer zoom levels.</source>
        <translation>El área necesita %1 teselas, más que el límite de %2: elija un área más pequeña o menos niveles de zoom.</translation>
    </message>
    <message>
        <source>Tiles from %1, taken offline by %2</source>
        <translation>Teselas de %1, descargadas para uso sin conexión por %2</translation>
    </message>
    <message>
        <source>not an image (%1, %2 bytes)</source>
        <translation>no es una imagen (%1, %2 bytes)</translation>
    </message>
    <message>
        <source>no answer within %1 s</source>
        <translation>sin respuesta en %1 s</translation>
    </message>
    <message>
        <source>%1 (after %2 attempts)</source>
        <translation>%1 (tras %2 intentos)</translation>
    </message>
</context>
<context>
    <name>sortie::mission::RouteEditor</name>
    <message>
        <source>Nothing is selected.</source>
        <translation>No hay nada seleccionado.</translation>
    </message>
    <message>
        <source>That is not a valid position.</source>
        <translation>Esa no es una posición válida.</translation>
    </message>
    <message>
        <source>There is no row %1 to insert at.</source>
        <translation>No hay ninguna fila %1 en la que insertar.</translation>
    </message>
    <message>
        <source>Add waypoint %1</source>
        <translation>Añadir waypoint %1</translation>
    </message>
    <message>
        <source>A move needs one position per waypoint.</source>
        <translation>Un desplazamiento necesita una posición por waypoint.</translation>
    </message>
    <message>
        <source>There is no row %1.</source>
        <translation>No hay ninguna fila %1.</translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>Mover %1</translation>
    </message>
    <message numerus="yes">
        <source>Move %n segment(s)</source>
        <translation>
            <numerusform>Mover %n segmento</numerusform>
            <numerusform>Mover %n segmentos</numerusform>
        </translation>
    </message>
    <message>
        <source>Row %1 is not a waypoint.</source>
        <translation>La fila %1 no es un waypoint.</translation>
    </message>
    <message>
        <source>The altitude needs a number.</source>
        <translation>La altitud necesita un número.</translation>
    </message>
    <message>
        <source>Set altitude to %1 m</source>
        <translation>Fijar altitud en %1 m</translation>
    </message>
    <message>
        <source>Set altitude type to %1</source>
        <translation>Fijar tipo de altitud en %1</translation>
    </message>
    <message>
        <source>Row %1 keeps its height %2: set it as %2, or change its altitude type first.</source>
        <translation>La fila %1 conserva su altura %2: indíquela en %2 o cambie antes su tipo de altitud.</translation>
    </message>
    <message>
        <source>Waypoint %1 is planned %2 and there is no terrain data under it: a height %3 cannot be converted.</source>
        <translation>El waypoint %1 está planificado en %2 y no hay datos de terreno bajo él: no se puede convertir una altura %3.</translation>
    </message>
    <message>
        <source>Set altitude to %1 m %2</source>
        <translation>Fijar altitud en %1 m %2</translation>
    </message>
    <message>
        <source>Set turn type to %1</source>
        <translation>Fijar tipo de giro en %1</translation>
    </message>
    <message>
        <source>No selected segment has a parameter &quot;%1&quot;.</source>
        <translation>Ningún segmento seleccionado tiene un parámetro «%1».</translation>
    </message>
    <message>
        <source>Set %1 to %2</source>
        <translation>Fijar %1 en %2</translation>
    </message>
    <message>
        <source>There is no action &quot;%1&quot;.</source>
        <translation>No existe la acción «%1».</translation>
    </message>
    <message>
        <source>Add action: %1</source>
        <translation>Añadir acción: %1</translation>
    </message>
    <message>
        <source>Remove action</source>
        <translation>Quitar acción</translation>
    </message>
    <message>
        <source>There is no action &quot;%1&quot; with these values.</source>
        <translation>No existe la acción «%1» con estos valores.</translation>
    </message>
    <message>
        <source>Edit action: %1</source>
        <translation>Editar acción: %1</translation>
    </message>
    <message>
        <source>Clear actions</source>
        <translation>Borrar acciones</translation>
    </message>
    <message>
        <source>An area scan needs at least three corners that enclose an area.</source>
        <translation>Un escaneo de área necesita al menos tres esquinas que encierren un área.</translation>
    </message>
    <message>
        <source>Add area scan</source>
        <translation>Añadir escaneo de área</translation>
    </message>
    <message>
        <source>Segment %1 has no point %2.</source>
        <translation>El segmento %1 no tiene punto %2.</translation>
    </message>
    <message>
        <source>Move point %1 of segment %2</source>
        <translation>Mover el punto %1 del segmento %2</translation>
    </message>
    <message>
        <source>Segment %1 has no edge there.</source>
        <translation>El segmento %1 no tiene ningún lado ahí.</translation>
    </message>
    <message>
        <source>Add a point to segment %1</source>
        <translation>Añadir un punto al segmento %1</translation>
    </message>
    <message numerus="yes">
        <source>This figure keeps at least %n point(s).</source>
        <translation>
            <numerusform>Esta figura conserva al menos %n punto.</numerusform>
            <numerusform>Esta figura conserva al menos %n puntos.</numerusform>
        </translation>
    </message>
    <message>
        <source>Remove point %1 of segment %2</source>
        <translation>Quitar el punto %1 del segmento %2</translation>
    </message>
    <message>
        <source>A radius is above 0 m.</source>
        <translation>Un radio es mayor que 0 m.</translation>
    </message>
    <message>
        <source>Segment %1 is no circle.</source>
        <translation>El segmento %1 no es un círculo.</translation>
    </message>
    <message>
        <source>Set the radius of segment %1 to %2 m</source>
        <translation>Fijar el radio del segmento %1 en %2 m</translation>
    </message>
    <message>
        <source>A point segment needs one valid position.</source>
        <translation>Un segmento de punto necesita una posición válida.</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>Añadir %1</translation>
    </message>
    <message>
        <source>Sortie has no description of the algorithm %1.</source>
        <translation>Sortie no tiene descripción del algoritmo %1.</translation>
    </message>
    <message numerus="yes">
        <source>%1 needs at least %n point(s)%2.</source>
        <translation>
            <numerusform>%1 necesita al menos %n punto%2.</numerusform>
            <numerusform>%1 necesita al menos %n puntos%2.</numerusform>
        </translation>
    </message>
    <message>
        <source> enclosing an area</source>
        <translation> que encierren un área</translation>
    </message>
    <message>
        <source>A route has no setting &quot;%1&quot;.</source>
        <translation>Una ruta no tiene ningún ajuste «%1».</translation>
    </message>
    <message>
        <source>%1 needs a number.</source>
        <translation>%1 necesita un número.</translation>
    </message>
    <message>
        <source>Set route %1</source>
        <translation>Fijar %1 de la ruta</translation>
    </message>
    <message>
        <source>Plan the start for %1</source>
        <translation>Planificar el inicio para %1</translation>
    </message>
    <message>
        <source>Start now</source>
        <translation>Iniciar ahora</translation>
    </message>
    <message>
        <source>An authorisation needs the zone&apos;s identifier.</source>
        <translation>Una autorización necesita el identificador de la zona.</translation>
    </message>
    <message>
        <source>Remove the authorisation for %1</source>
        <translation>Quitar la autorización para %1</translation>
    </message>
    <message>
        <source>Record authorisation %1 for %2</source>
        <translation>Registrar la autorización %1 para %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no start time: type it as %2, e.g. %3.</source>
        <translation>«%1» no es una hora de inicio: escríbala como %2, p. ej. %3.</translation>
    </message>
</context>
<context>
    <name>sortie::mission::SegmentEditorModel</name>
    <message>
        <source>A parameter Sortie has no description of: kept and sent as typed.</source>
        <translation>Un parámetro que Sortie no tiene descrito: se conserva y se envía tal como se escribió.</translation>
    </message>
    <message>
        <source>%1 (vehicle profile)</source>
        <translation>%1 (perfil de vehículo)</translation>
    </message>
    <message>
        <source>%1 needs a number, not &quot;%2&quot;.</source>
        <translation>%1 necesita un número, no «%2».</translation>
    </message>
    <message>
        <source>%1 m high · %2 cm/px · footprint %3 × %4 m · passes %5 m apart · photo every %6 m · %7 photos</source>
        <translation>%1 m de altura · %2 cm/px · huella %3 × %4 m · pasadas a %5 m · foto cada %6 m · %7 fotos</translation>
    </message>
</context>
<context>
    <name>sortie::mission::SegmentPreview</name>
    <message>
        <source>This segment cannot be planned.</source>
        <translation>Este segmento no se puede planificar.</translation>
    </message>
</context>
<context>
    <name>sortie::mission::WaypointActionsModel</name>
    <message>
        <source>Actions at waypoint %1</source>
        <translation>Acciones en el waypoint %1</translation>
    </message>
    <message>
        <source>Actions at %1 waypoints</source>
        <translation>Acciones en %1 waypoints</translation>
    </message>
    <message>
        <source>There is no action &quot;%1&quot;.</source>
        <translation>No existe la acción «%1».</translation>
    </message>
    <message>
        <source>This action has no field &quot;%1&quot;.</source>
        <translation>Esta acción no tiene ningún campo «%1».</translation>
    </message>
    <message>
        <source>Choose an action to add.</source>
        <translation>Elija una acción para añadir.</translation>
    </message>
</context>
<context>
    <name>sortie::preflight::PreflightChecklists</name>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>No se puede leer %1: %2</translation>
    </message>
</context>
<context>
    <name>sortie::preflight::VehicleChecklist</name>
    <message>
        <source>2D fix</source>
        <translation>posición 2D</translation>
    </message>
    <message>
        <source>3D fix</source>
        <translation>posición 3D</translation>
    </message>
    <message>
        <source>RTK float</source>
        <translation>RTK flotante</translation>
    </message>
    <message>
        <source>RTK fixed</source>
        <translation>RTK fijo</translation>
    </message>
    <message>
        <source>no fix</source>
        <translation>sin posición</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Link to the vehicle</source>
        <translation>Enlace con el vehículo</translation>
    </message>
    <message>
        <source>GPS fix</source>
        <translation>Posición GPS</translation>
    </message>
    <message>
        <source>Satellites</source>
        <translation>Satélites</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Batería</translation>
    </message>
    <message>
        <source>Home position</source>
        <translation>Posición de casa</translation>
    </message>
    <message>
        <source>Route on board</source>
        <translation>Ruta a bordo</translation>
    </message>
    <message>
        <source>Route check</source>
        <translation>Comprobación de la ruta</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Cámara</translation>
    </message>
    <message>
        <source>ticked</source>
        <translation>marcado</translation>
    </message>
    <message>
        <source>not reported over this vehicle&apos;s link</source>
        <translation>no se informa por el enlace de este vehículo</translation>
    </message>
    <message>
        <source>to tick</source>
        <translation>por marcar</translation>
    </message>
    <message>
        <source>Sortie has uploaded no route to it</source>
        <translation>Sortie no le ha cargado ninguna ruta</translation>
    </message>
    <message>
        <source>its route is not the one open</source>
        <translation>su ruta no es la abierta</translation>
    </message>
    <message>
        <source>not known: no fresh telemetry</source>
        <translation>desconocido: sin telemetría reciente</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>conectado</translation>
    </message>
    <message>
        <source>no fresh telemetry</source>
        <translation>sin telemetría reciente</translation>
    </message>
    <message>
        <source>%1 (%2 needed)</source>
        <translation>%1 (se necesita %2)</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>%1 % (%2 % needed)</source>
        <translation>%1 % (se necesita %2 %)</translation>
    </message>
    <message>
        <source>set</source>
        <translation>fijada</translation>
    </message>
    <message>
        <source>not set</source>
        <translation>sin fijar</translation>
    </message>
    <message>
        <source>the planned route</source>
        <translation>la ruta planificada</translation>
    </message>
    <message>
        <source>differs from the planned route: upload it</source>
        <translation>difiere de la ruta planificada: cárguela</translation>
    </message>
    <message>
        <source>no errors</source>
        <translation>sin errores</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errores</numerusform>
        </translation>
    </message>
    <message>
        <source>stream reported</source>
        <translation>flujo anunciado</translation>
    </message>
    <message>
        <source>no stream reported</source>
        <translation>ningún flujo anunciado</translation>
    </message>
</context>
<context>
    <name>sortie::resume::MissionResume</name>
    <message>
        <source>The route</source>
        <translation>La ruta</translation>
    </message>
    <message numerus="yes">
        <source>%1 stopped flying to waypoint %2 of %3, after %n photo(s).</source>
        <translation>
            <numerusform>%1 se detuvo volando al punto %2 de %3, tras %n foto.</numerusform>
            <numerusform>%1 se detuvo volando al punto %2 de %3, tras %n fotos.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 stopped flying to waypoint %2 of %3.</source>
        <translation>%1 se detuvo volando al punto %2 de %3.</translation>
    </message>
    <message>
        <source>There is nothing to resume: no vehicle stands with a route flown part of the way.</source>
        <translation>No hay nada que reanudar: ningún vehículo está parado con una ruta volada en parte.</translation>
    </message>
    <message>
        <source>The vehicle took no photo on this route.</source>
        <translation>El vehículo no tomó ninguna foto en esta ruta.</translation>
    </message>
    <message>
        <source>The vehicle reached no waypoint of this route.</source>
        <translation>El vehículo no alcanzó ningún punto de esta ruta.</translation>
    </message>
    <message>
        <source>Resume the mission</source>
        <translation>Reanudar la misión</translation>
    </message>
</context>
<context>
    <name>sortie::secrets::PasswordVault</name>
    <message>
        <source>the keyring did not answer</source>
        <translation>el llavero no respondió</translation>
    </message>
</context>
<context>
    <name>sortie::traffic::SbsFeed</name>
    <message>
        <source>no answer within %1 s</source>
        <translation>sin respuesta en %1 s</translation>
    </message>
    <message>
        <source>the receiver closed the connection</source>
        <translation>el receptor cerró la conexión</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not host:port</source>
        <translation>«%1» no es host:puerto</translation>
    </message>
    <message>
        <source>receiver off</source>
        <translation>receptor apagado</translation>
    </message>
    <message>
        <source>receiver: %1</source>
        <translation>receptor: %1</translation>
    </message>
    <message>
        <source>receiver: connecting to %1</source>
        <translation>receptor: conectando a %1</translation>
    </message>
    <message>
        <source>receiver %1</source>
        <translation>receptor %1</translation>
    </message>
    <message>
        <source>receiver: %1; again in %2 s</source>
        <translation>receptor: %1; nuevo intento en %2 s</translation>
    </message>
</context>
<context>
    <name>sortie::ui::AppSettings</name>
    <message>
        <source>The password an earlier version kept in the settings file is now in the keyring.</source>
        <translation>La contraseña que una versión anterior guardaba en el archivo de ajustes está ahora en el llavero.</translation>
    </message>
    <message>
        <source>The password an earlier version kept in the settings file was erased from it; the keyring refused it (%1), so it is not remembered.</source>
        <translation>La contraseña que una versión anterior guardaba en el archivo de ajustes se borró de él; el llavero la rechazó (%1), así que no se recuerda.</translation>
    </message>
    <message>
        <source>The keyring refused the password (%1): it is not remembered.</source>
        <translation>El llavero rechazó la contraseña (%1): no se recuerda.</translation>
    </message>
    <message>
        <source>The remembered password could not be read from the keyring (%1).</source>
        <translation>No se pudo leer del llavero la contraseña recordada (%1).</translation>
    </message>
    <message>
        <source>The password could not be removed from the keyring (%1).</source>
        <translation>No se pudo quitar la contraseña del llavero (%1).</translation>
    </message>
    <message>
        <source>No keyring is reachable, so the password cannot be remembered (%1).</source>
        <translation>No hay ningún llavero accesible, así que no se puede recordar la contraseña (%1).</translation>
    </message>
    <message>
        <source>The password an earlier version kept in the settings file was erased from it.</source>
        <translation>La contraseña que una versión anterior guardaba en el archivo de ajustes se borró de él.</translation>
    </message>
</context>
<context>
    <name>sortie::ui::AttitudeIndicator</name>
    <message>
        <source>no attitude</source>
        <translation>sin actitud</translation>
    </message>
</context>
<context>
    <name>sortie::ui::ConflictLayer</name>
    <message>
        <source>%1 at %2:%3, %4 m / %5 m</source>
        <translation>%1 en %2:%3, %4 m / %5 m</translation>
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
        <translation>desconectado</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>conectando</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>conectado</translation>
    </message>
    <message>
        <source>link lost</source>
        <translation>enlace perdido</translation>
    </message>
</context>
<context>
    <name>sortie::ui::ElevationProfileView</name>
    <message>
        <source>Leg %1 · %2 · ground %3 · altitude %4 · clearance %5</source>
        <translation>Tramo %1 · %2 · terreno %3 · altitud %4 · margen %5</translation>
    </message>
    <message>
        <source>no data</source>
        <translation>sin datos</translation>
    </message>
    <message>
        <source>Add two waypoints to see the terrain profile</source>
        <translation>Añada dos waypoints para ver el perfil del terreno</translation>
    </message>
    <message>
        <source>No terrain source</source>
        <translation>Sin fuente de terreno</translation>
    </message>
    <message>
        <source>Ground: %1</source>
        <translation>Terreno: %1</translation>
    </message>
    <message>
        <source>lowest clearance %1</source>
        <translation>margen mínimo %1</translation>
    </message>
    <message>
        <source>clearance unknown</source>
        <translation>margen desconocido</translation>
    </message>
    <message>
        <source>no return</source>
        <translation>sin retorno</translation>
    </message>
    <message>
        <source>battery change</source>
        <translation>cambio de batería</translation>
    </message>
</context>
<context>
    <name>sortie::ui::EnduranceLayer</name>
    <message>
        <source>Battery change</source>
        <translation>Cambio de batería</translation>
    </message>
    <message>
        <source>Battery change needed</source>
        <translation>Se necesita cambio de batería</translation>
    </message>
    <message>
        <source>No return</source>
        <translation>Sin retorno</translation>
    </message>
</context>
<context>
    <name>sortie::ui::FlightStatus</name>
    <message>
        <source>mission complete</source>
        <translation>misión completada</translation>
    </message>
    <message>
        <source>waypoint %1 of %2</source>
        <translation>waypoint %1 de %2</translation>
    </message>
    <message>
        <source>1 waypoint on board</source>
        <translation>1 waypoint a bordo</translation>
    </message>
    <message>
        <source>%1 waypoints on board</source>
        <translation>%1 waypoints a bordo</translation>
    </message>
    <message>
        <source>no mission on board</source>
        <translation>ninguna misión a bordo</translation>
    </message>
</context>
<context>
    <name>sortie::ui::GlanceStatus</name>
    <message>
        <source>No server</source>
        <translation>Sin servidor</translation>
    </message>
    <message>
        <source>No vehicle</source>
        <translation>Sin vehículo</translation>
    </message>
    <message>
        <source>GPS —</source>
        <translation>GPS —</translation>
    </message>
    <message>
        <source>No fix</source>
        <translation>Sin posición</translation>
    </message>
    <message>
        <source>2D fix</source>
        <translation>Posición 2D</translation>
    </message>
    <message>
        <source>3D fix</source>
        <translation>Posición 3D</translation>
    </message>
    <message>
        <source>RTK float</source>
        <translation>RTK flotante</translation>
    </message>
    <message>
        <source>RTK fixed</source>
        <translation>RTK fija</translation>
    </message>
    <message>
        <source>%1, %2 sats</source>
        <translation>%1, %2 sat.</translation>
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
        <translation>Batería —</translation>
    </message>
    <message>
        <source>Link lost</source>
        <translation>Enlace perdido</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>Link —</source>
        <translation>Enlace —</translation>
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
        <translation>No se ha indicado ningún archivo MBTiles.</translation>
    </message>
    <message>
        <source>The MBTiles file has no tile %1.</source>
        <translation>El archivo MBTiles no tiene la tesela %1.</translation>
    </message>
    <message>
        <source>Tile %1 in the MBTiles file is not a raster image.</source>
        <translation>La tesela %1 del archivo MBTiles no es una imagen ráster.</translation>
    </message>
</context>
<context>
    <name>sortie::ui::OfflineTileSource</name>
    <message>
        <source>Offline base map</source>
        <translation>Mapa base sin conexión</translation>
    </message>
    <message>
        <source>Land outlines: Natural Earth</source>
        <translation>Contornos de tierra: Natural Earth</translation>
    </message>
    <message>
        <source>The built-in land outlines could not be read: %1</source>
        <translation>No se pudieron leer los contornos de tierra integrados: %1</translation>
    </message>
</context>
<context>
    <name>sortie::ui::PhotoLayer</name>
    <message>
        <source>Hole %1 m²</source>
        <translation>Hueco %1 m²</translation>
    </message>
</context>
<context>
    <name>sortie::ui::RasterFileCheck</name>
    <message numerus="yes">
        <source>%n file(s) left out, the others are used:</source>
        <translation>
            <numerusform>%n archivo omitido, se usan los demás:</numerusform>
            <numerusform>%n archivos omitidos, se usan los demás:</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>and %n more (in the log)</source>
        <translation>
            <numerusform>y %n más (en el registro)</numerusform>
            <numerusform>y %n más (en el registro)</numerusform>
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
        <translation>ahora</translation>
    </message>
    <message>
        <source>No data yet</source>
        <translation>Aún no hay datos</translation>
    </message>
    <message>
        <source>Choose a vehicle</source>
        <translation>Elija un vehículo</translation>
    </message>
</context>
<context>
    <name>sortie::ui::TerrainProfileModel</name>
    <message>
        <source>no terrain source</source>
        <translation>sin fuente de terreno</translation>
    </message>
    <message>
        <source>no terrain data (tried: %1)</source>
        <translation>sin datos de terreno (se probó: %1)</translation>
    </message>
    <message>
        <source> · loading…</source>
        <translation> · cargando…</translation>
    </message>
    <message>
        <source>under this waypoint</source>
        <translation>bajo este waypoint</translation>
    </message>
    <message>
        <source>under this segment&apos;s points</source>
        <translation>bajo los puntos de este segmento</translation>
    </message>
    <message>
        <source>Asking for the ground %1…</source>
        <translation>Consultando el terreno %1…</translation>
    </message>
    <message>
        <source>No terrain data %1 (tried: %2)</source>
        <translation>No hay datos de terreno %1 (se probó: %2)</translation>
    </message>
    <message>
        <source>Ground %1, metres above sea level (EGM96), from %2</source>
        <translation>Terreno %1, metros sobre el nivel del mar (EGM96), de %2</translation>
    </message>
    <message>
        <source>; some points have no data (tried: %1)</source>
        <translation>; algunos puntos no tienen datos (se probó: %1)</translation>
    </message>
</context>
<context>
    <name>sortie::ui::Theme</name>
    <message>
        <source>System colours</source>
        <translation>Colores del sistema</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Claro</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Oscuro</translation>
    </message>
    <message>
        <source>Sunlight (high contrast)</source>
        <translation>Luz solar (alto contraste)</translation>
    </message>
</context>
<context>
    <name>sortie::ui::TileManager</name>
    <message>
        <source>Offline base map</source>
        <translation>Mapa base sin conexión</translation>
    </message>
    <message>
        <source>%1 — offline base map shown</source>
        <translation>%1 — se muestra el mapa base sin conexión</translation>
    </message>
    <message numerus="yes">
        <source>%1: loading %n tile(s)</source>
        <translation>
            <numerusform>%1: cargando %n tesela</numerusform>
            <numerusform>%1: cargando %n teselas</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %n tile(s) missing — %2</source>
        <translation>
            <numerusform>%1: falta %n tesela — %2</numerusform>
            <numerusform>%1: faltan %n teselas — %2</numerusform>
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
        <translation> std</translation>
    </message>
    <message>
        <source> climbing</source>
        <translation> ascendiendo</translation>
    </message>
    <message>
        <source> descending</source>
        <translation> descendiendo</translation>
    </message>
</context>
<context>
    <name>sortie::ui::Translations</name>
    <message>
        <source>System language</source>
        <translation>Idioma del sistema</translation>
    </message>
</context>
<context>
    <name>sortie::ui::VideoItem</name>
    <message>
        <source>No video for this vehicle</source>
        <translation>No hay vídeo para este vehículo</translation>
    </message>
    <message>
        <source>hardware decoding (%1)</source>
        <translation>decodificación por hardware (%1)</translation>
    </message>
    <message>
        <source>software decoding (%1)</source>
        <translation>decodificación por software (%1)</translation>
    </message>
</context>
<context>
    <name>sortie::ui::XyzTileSource</name>
    <message>
        <source>Web tiles</source>
        <translation>Teselas web</translation>
    </message>
    <message>
        <source>Tile %1 is not an image.</source>
        <translation>La tesela %1 no es una imagen.</translation>
    </message>
    <message>
        <source>Tile %1 is neither in the offline pack nor in the cache (cache only: the network is not used).</source>
        <translation>La tesela %1 no está ni en el paquete sin conexión ni en la caché (solo caché: no se usa la red).</translation>
    </message>
    <message>
        <source>Tile %1 is not in the cache and the tile server is unreachable.</source>
        <translation>La tesela %1 no está en la caché y el servidor de teselas no es accesible.</translation>
    </message>
    <message>
        <source>No tile file %1.</source>
        <translation>No existe el archivo de tesela %1.</translation>
    </message>
    <message>
        <source>The tile server answered HTTP %1 for tile %2.</source>
        <translation>El servidor de teselas respondió HTTP %1 para la tesela %2.</translation>
    </message>
    <message>
        <source>Tile server unreachable (%1).</source>
        <translation>Servidor de teselas no accesible (%1).</translation>
    </message>
    <message>
        <source>Tile %1 is %2.</source>
        <translation>La tesela %1 es %2.</translation>
    </message>
</context>
<context>
    <name>sortie::ui::ZoneLayer</name>
    <message>
        <source>drawn on the map</source>
        <translation>dibujada en el mapa</translation>
    </message>
    <message>
        <source>%1 (%2 zone)
Source: %3%4
Floor %5, ceiling %6</source>
        <translation>%1 (zona: %2)
Fuente: %3%4
Base %5, techo %6</translation>
    </message>
    <message>
        <source>
Not checked: %1</source>
        <translation>
No comprobada: %1</translation>
    </message>
    <message>
        <source>
Switched off: not checked</source>
        <translation>
Desactivada: no comprobada</translation>
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
Motivo: %1</translation>
    </message>
    <message>
        <source>
When: %1</source>
        <translation>
Cuándo: %1</translation>
    </message>
    <message>
        <source>
Not in force during the planned flight</source>
        <translation>
No vigente durante el vuelo previsto</translation>
    </message>
    <message>
        <source>
Authority: %1</source>
        <translation>
Autoridad: %1</translation>
    </message>
</context>
<context>
    <name>sortie::vehicle::CommandLog</name>
    <message>
        <source>sent</source>
        <translation>enviada</translation>
    </message>
    <message>
        <source>done</source>
        <translation>completada</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fallida</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>cancelada</translation>
    </message>
    <message>
        <source>alert</source>
        <translation>alerta</translation>
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
        <translation>Falta %1 de GStreamer: instale %2</translation>
    </message>
    <message>
        <source>No %1 decoder: install %2</source>
        <translation>No hay decodificador %1: instale %2</translation>
    </message>
    <message>
        <source>The video pipeline could not be built: %1</source>
        <translation>No se pudo construir la cadena de vídeo: %1</translation>
    </message>
    <message>
        <source>No %1: install %2</source>
        <translation>No hay %1: instale %2</translation>
    </message>
    <message>
        <source>A GStreamer plugin is missing: %1</source>
        <translation>Falta un plugin de GStreamer: %1</translation>
    </message>
    <message>
        <source>the stream ended</source>
        <translation>el flujo terminó</translation>
    </message>
    <message>
        <source>no frame for %1 s</source>
        <translation>sin imagen durante %1 s</translation>
    </message>
    <message>
        <source>no frame since the last attempt</source>
        <translation>sin imagen desde el último intento</translation>
    </message>
    <message>
        <source>nothing received yet</source>
        <translation>aún no se ha recibido nada</translation>
    </message>
    <message>
        <source>No video URL</source>
        <translation>Sin URL de vídeo</translation>
    </message>
    <message>
        <source>Video stopped</source>
        <translation>Vídeo detenido</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>Conectando con %1…</translation>
    </message>
    <message>
        <source>Connecting to %1… (%2)</source>
        <translation>Conectando con %1… (%2)</translation>
    </message>
    <message>
        <source>%1, %2×%3, %4 decoding (%5)</source>
        <translation>%1, %2×%3, decodificación por %4 (%5)</translation>
    </message>
    <message>
        <source>hardware</source>
        <translation>hardware</translation>
    </message>
    <message>
        <source>software</source>
        <translation>software</translation>
    </message>
    <message>
        <source>No video since %1 (%2); reconnecting</source>
        <translation>Sin vídeo desde %1 (%2); reconectando</translation>
    </message>
</context>
<context>
    <name>sortie::video::VideoRuntime</name>
    <message>
        <source>GStreamer did not start: %1</source>
        <translation>GStreamer no arrancó: %1</translation>
    </message>
</context>
</TS>
