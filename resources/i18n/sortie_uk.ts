<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="uk">
<context>
    <name>ActionEditor</name>
    <message>
        <source>The selected waypoints have different actions: these are the first one&apos;s. An edit applies where they match; an added action goes to all.</source>
        <translation>Вибрані точки мають різні дії: показано дії першої. Зміна застосовується там, де вони збігаються; додана дія додається до всіх.</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Видалити</translation>
    </message>
    <message>
        <source>Sent by the server; kept and sent back unchanged.</source>
        <translation>Надіслано сервером; зберігається й повертається без змін.</translation>
    </message>
    <message>
        <source>Add action</source>
        <translation>Додати дію</translation>
    </message>
    <message>
        <source>Remove all</source>
        <translation>Видалити всі</translation>
    </message>
</context>
<context>
    <name>ActionVariants</name>
    <message>
        <source>%1 is either on or off</source>
        <translation>%1: лише увімк. або вимк.</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not one of its choices</source>
        <translation>%1: «%2» не є одним із варіантів</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation>%1: «%2» не є числом</translation>
    </message>
    <message>
        <source>%1: %2 is not a whole number</source>
        <translation>%1: %2 не є цілим числом</translation>
    </message>
    <message>
        <source>%1: %2 is below %3 %4</source>
        <translation>%1: %2 менше за %3 %4</translation>
    </message>
    <message>
        <source>%1: %2 is above %3 %4</source>
        <translation>%1: %2 більше за %3 %4</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Камера</translation>
    </message>
    <message>
        <source>Take a photo</source>
        <translation>Зробити фото</translation>
    </message>
    <message>
        <source>Start video</source>
        <translation>Почати відео</translation>
    </message>
    <message>
        <source>Stop video</source>
        <translation>Зупинити відео</translation>
    </message>
    <message>
        <source>Toggle video</source>
        <translation>Перемкнути відео</translation>
    </message>
    <message>
        <source>Photos by distance</source>
        <translation>Фото за відстанню</translation>
    </message>
    <message>
        <source>Every</source>
        <translation>Кожні</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>Shots (0: until stopped)</source>
        <translation>Знімків (0: до зупинки)</translation>
    </message>
    <message>
        <source>Start after</source>
        <translation>Почати через</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <source>Photos by time</source>
        <translation>Фото за часом</translation>
    </message>
    <message>
        <source>Wait</source>
        <translation>Очікування</translation>
    </message>
    <message>
        <source>For</source>
        <translation>Протягом</translation>
    </message>
    <message>
        <source>Until the operator continues</source>
        <translation>Доки оператор не продовжить</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Курс</translation>
    </message>
    <message>
        <source>From the course</source>
        <translation>Від напрямку руху</translation>
    </message>
    <message>
        <source>Point of interest</source>
        <translation>Точка інтересу</translation>
    </message>
    <message>
        <source>Latitude</source>
        <translation>Широта</translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation>Довгота</translation>
    </message>
    <message>
        <source>Altitude</source>
        <translation>Висота</translation>
    </message>
    <message>
        <source>Altitude type</source>
        <translation>Тип висоти</translation>
    </message>
    <message>
        <source>Above ground (AGL)</source>
        <translation>Над поверхнею (AGL)</translation>
    </message>
    <message>
        <source>Above sea level (AMSL)</source>
        <translation>Над рівнем моря (AMSL)</translation>
    </message>
    <message>
        <source>Gimbal and zoom</source>
        <translation>Підвіс і зум</translation>
    </message>
    <message>
        <source>Tilt (90: down)</source>
        <translation>Нахил (90: вниз)</translation>
    </message>
    <message>
        <source>Roll</source>
        <translation>Крен</translation>
    </message>
    <message>
        <source>Yaw</source>
        <translation>Рискання</translation>
    </message>
    <message>
        <source>Zoom level</source>
        <translation>Рівень зуму</translation>
    </message>
    <message>
        <source>Panorama</source>
        <translation>Панорама</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Кут</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Крок</translation>
    </message>
    <message>
        <source>Pause per step</source>
        <translation>Пауза на кроці</translation>
    </message>
    <message>
        <source>Rotation speed</source>
        <translation>Швидкість обертання</translation>
    </message>
    <message>
        <source>°/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <source>Clockwise</source>
        <translation>За годинниковою стрілкою</translation>
    </message>
    <message>
        <source>Video</source>
        <translation>Відео</translation>
    </message>
    <message>
        <source>Set servo</source>
        <translation>Задати сервопривід</translation>
    </message>
    <message>
        <source>Servo</source>
        <translation>Сервопривід</translation>
    </message>
    <message>
        <source>PWM</source>
        <translation>PWM</translation>
    </message>
    <message>
        <source>Repeat servo</source>
        <translation>Повтор сервопривода</translation>
    </message>
    <message>
        <source>Cycle time</source>
        <translation>Період циклу</translation>
    </message>
    <message>
        <source>Repeats</source>
        <translation>Повторів</translation>
    </message>
    <message>
        <source>Switch to hover (VTOL)</source>
        <translation>Перехід у висіння (VTOL)</translation>
    </message>
    <message>
        <source>Switch to fixed-wing</source>
        <translation>Перехід у літаковий режим</translation>
    </message>
    <message>
        <source>Lidar recording</source>
        <translation>Запис лідара</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>Запис</translation>
    </message>
    <message>
        <source>Lidar calibration</source>
        <translation>Калібрування лідара</translation>
    </message>
    <message>
        <source>Distance</source>
        <translation>Відстань</translation>
    </message>
    <message>
        <source>Times</source>
        <translation>Разів</translation>
    </message>
    <message>
        <source>Hop</source>
        <translation>Підскок</translation>
    </message>
    <message>
        <source>Descent altitude</source>
        <translation>Висота зниження</translation>
    </message>
    <message>
        <source>Drop payload</source>
        <translation>Скинути вантаж</translation>
    </message>
    <message>
        <source>Descent speed</source>
        <translation>Швидкість зниження</translation>
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
        <translation>геозона маршруту</translation>
    </message>
    <message>
        <source>the open route</source>
        <translation>відкритий маршрут</translation>
    </message>
    <message>
        <source>%1 (kept as %2)</source>
        <translation>%1 (збережено як %2)</translation>
    </message>
    <message>
        <source>drawn</source>
        <translation>намальована</translation>
    </message>
    <message>
        <source>server</source>
        <translation>сервер</translation>
    </message>
    <message>
        <source>file</source>
        <translation>файл</translation>
    </message>
    <message>
        <source>server zone %1, edited here</source>
        <translation>зона сервера %1, редагується тут</translation>
    </message>
    <message>
        <source>today</source>
        <translation>сьогодні</translation>
    </message>
    <message>
        <source>yesterday</source>
        <translation>вчора</translation>
    </message>
    <message numerus="yes">
        <source>%n day(s) ago</source>
        <translation>
            <numerusform>%n день тому</numerusform>
            <numerusform>%n дні тому</numerusform>
            <numerusform>%n днів тому</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>AirspaceRule</name>
    <message>
        <source>floor %1, ceiling %2</source>
        <translation>нижня межа %1, верхня межа %2</translation>
    </message>
    <message>
        <source>at %1</source>
        <translation>на %1</translation>
    </message>
    <message>
        <source>from %1 to %2</source>
        <translation>від %1 до %2</translation>
    </message>
    <message>
        <source>; its height there is unknown (no terrain data), so it counts as inside</source>
        <translation>; її висота там невідома (немає даних рельєфу), тому вважається, що вона всередині</translation>
    </message>
    <message>
        <source>Leg %1 passes within %2 of %3 &apos;%4&apos; (buffer %5).</source>
        <translation>Ділянка %1 проходить за %2 від %3 «%4» (буфер %5).</translation>
    </message>
    <message>
        <source>exclusion zone</source>
        <translation>заборонної зони</translation>
    </message>
    <message>
        <source>the edge of inclusion zone</source>
        <translation>межі дозвільної зони</translation>
    </message>
    <message>
        <source>Leg %1 enters &apos;%2&apos; %3 (%4)</source>
        <translation>Ділянка %1 входить у «%2» %3 (%4)</translation>
    </message>
    <message>
        <source>Leg %1 leaves &apos;%2&apos; %3 (%4)</source>
        <translation>Ділянка %1 виходить із «%2» %3 (%4)</translation>
    </message>
    <message>
        <source>Message: %1</source>
        <translation>Повідомлення: %1</translation>
    </message>
    <message>
        <source>Reason: %1.</source>
        <translation>Причина: %1.</translation>
    </message>
    <message>
        <source>Authority: %1.</source>
        <translation>Орган: %1.</translation>
    </message>
    <message>
        <source>Applies: %1.</source>
        <translation>Діє: %1.</translation>
    </message>
    <message>
        <source>Leg %1 enters the prohibited zone &apos;%2&apos; (%3, volume %4) %5 (%6)</source>
        <translation>Ділянка %1 входить у заборонену зону «%2» (%3, об’єм %4) %5 (%6)</translation>
    </message>
    <message>
        <source>Leg %1 enters &apos;%2&apos; (%3, volume %4) %5 (%6), which needs an authorisation; none is recorded</source>
        <translation>Ділянка %1 входить у «%2» (%3, об’єм %4) %5 (%6), де потрібен дозвіл; жодного не записано</translation>
    </message>
    <message>
        <source>Leg %1 enters &apos;%2&apos; (%3, volume %4) %5 (%6) under authorisation %7</source>
        <translation>Ділянка %1 входить у «%2» (%3, об’єм %4) %5 (%6) за дозволом %7</translation>
    </message>
    <message>
        <source>Leg %1 enters the conditional zone &apos;%2&apos; (%3, volume %4) %5 (%6)</source>
        <translation>Ділянка %1 входить у зону з умовами «%2» (%3, об’єм %4) %5 (%6)</translation>
    </message>
    <message>
        <source>Leg %1 passes through &apos;%2&apos; (%3, volume %4) %5 (%6), a zone with no restriction</source>
        <translation>Ділянка %1 проходить через «%2» (%3, об’єм %4) %5 (%6), зону без обмежень</translation>
    </message>
</context>
<context>
    <name>AlertBanner</name>
    <message>
        <source>Too close: %1</source>
        <translation>Надто близько: %1</translation>
    </message>
    <message>
        <source>Airspace: %1</source>
        <translation>Повітряний простір: %1</translation>
    </message>
    <message>
        <source>Return home</source>
        <translation>Додому</translation>
    </message>
</context>
<context>
    <name>AlgorithmDefinition</name>
    <message>
        <source>%1 must be set</source>
        <translation>%1 має бути задано</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1: «%2» не є числом</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a whole number</source>
        <translation>%1: «%2» не є цілим числом</translation>
    </message>
    <message>
        <source>%1: %2 is below the minimum of %3</source>
        <translation>%1: %2 менше за мінімум %3</translation>
    </message>
    <message>
        <source>%1: %2 is above the maximum of %3</source>
        <translation>%1: %2 більше за максимум %3</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is neither true nor false</source>
        <translation>%1: «%2» — ні true, ні false</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not one of its choices</source>
        <translation>%1: «%2» не є одним із варіантів</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; does not have the expected form</source>
        <translation>%1: «%2» має неочікувану форму</translation>
    </message>
</context>
<context>
    <name>AreaScanPlanner</name>
    <message>
        <source>The camera needs a positive sensor size, focal length and image size.</source>
        <translation>Камері потрібні додатні розмір сенсора, фокусна відстань і розмір зображення.</translation>
    </message>
    <message>
        <source>Overlaps must be between 0 and 95 %.</source>
        <translation>Перекриття мають бути від 0 до 95 %.</translation>
    </message>
    <message>
        <source>The scan altitude (or ground sample distance) must be positive.</source>
        <translation>Висота сканування (або GSD) має бути додатною.</translation>
    </message>
    <message>
        <source>The turnaround distance must not be negative.</source>
        <translation>Відстань розвороту не може бути від’ємною.</translation>
    </message>
</context>
<context>
    <name>AtomicFile</name>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Не вдається записати %1: %2</translation>
    </message>
</context>
<context>
    <name>AutosaveDirectory</name>
    <message>
        <source>Cannot create the autosave folder %1</source>
        <translation>Не вдається створити теку автозбереження %1</translation>
    </message>
</context>
<context>
    <name>AutosaveRecord</name>
    <message>
        <source>the autosave holds no &quot;%1&quot; route</source>
        <translation>автозбереження не містить маршруту «%1»</translation>
    </message>
    <message>
        <source>the &quot;%1&quot; document holds %2 routes, not one</source>
        <translation>документ «%1» містить маршрутів: %2, а не один</translation>
    </message>
    <message>
        <source>not a Sortie autosave (&quot;format&quot; is not &quot;sortie-autosave&quot;)</source>
        <translation>не автозбереження Sortie (&quot;format&quot; не &quot;sortie-autosave&quot;)</translation>
    </message>
    <message>
        <source>autosave format version %1 is not one this Sortie reads (1)</source>
        <translation>версію формату автозбереження %1 ця версія Sortie не читає (1)</translation>
    </message>
    <message>
        <source>&quot;savedAt&quot; is not a date and time</source>
        <translation>&quot;savedAt&quot; не є датою й часом</translation>
    </message>
</context>
<context>
    <name>AutosaveWriter</name>
    <message>
        <source>Cannot remove %1: %2</source>
        <translation>Не вдається видалити %1: %2</translation>
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
        <translation>Типова 1&quot; 20 MP</translation>
    </message>
</context>
<context>
    <name>CertificateFingerprint</name>
    <message>
        <source>%1: %2 holds no PEM certificate</source>
        <translation>%1: %2 не містить сертифіката PEM</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is neither a SHA-256 fingerprint (64 hex digits) nor a certificate file</source>
        <translation>%1: «%2» не є ні відбитком SHA-256 (64 шістнадцяткові цифри), ні файлом сертифіката</translation>
    </message>
</context>
<context>
    <name>Checklist</name>
    <message>
        <source>unknown key &quot;%1&quot;</source>
        <translation>невідомий ключ «%1»</translation>
    </message>
    <message>
        <source>an item the operator ticks has no &quot;check&quot;; leave it out</source>
        <translation>пункт, який позначає оператор, не має «check»; приберіть його</translation>
    </message>
    <message>
        <source>an item to tick needs a &quot;title&quot;</source>
        <translation>пункту для позначення потрібен «title»</translation>
    </message>
    <message>
        <source>&quot;%1&quot; takes no minimum</source>
        <translation>«%1» не має мінімуму</translation>
    </message>
    <message>
        <source>%1 is outside %2..%3</source>
        <translation>%1 поза межами %2..%3</translation>
    </message>
    <message>
        <source>&quot;%1&quot; needs a &quot;minimum&quot;</source>
        <translation>«%1» потребує «minimum»</translation>
    </message>
    <message>
        <source>an empty list holds nothing back; say &quot;required&quot;: false instead</source>
        <translation>порожній список нічого не затримує; напишіть натомість &quot;required&quot;: false</translation>
    </message>
    <message>
        <source>Sortie&apos;s default checklist</source>
        <translation>Типовий контрольний список Sortie</translation>
    </message>
    <message>
        <source>Propellers fitted and tight</source>
        <translation>Пропелери встановлені й затягнуті</translation>
    </message>
    <message>
        <source>Take-off area clear of people</source>
        <translation>У зоні зльоту немає людей</translation>
    </message>
    <message>
        <source>Payload and battery secured</source>
        <translation>Корисне навантаження й батарею закріплено</translation>
    </message>
    <message>
        <source>a checklist needs at least one item</source>
        <translation>контрольному списку потрібен хоча б один пункт</translation>
    </message>
</context>
<context>
    <name>ChecklistPanel</name>
    <message>
        <source>Pre-flight checklist</source>
        <translation>Передпольотний контрольний список</translation>
    </message>
    <message>
        <source>Ready to arm and fly the mission</source>
        <translation>Готовий до ввімкнення й польоту за місією</translation>
    </message>
    <message>
        <source>Ready to arm; Auto waits</source>
        <translation>Готовий до ввімкнення; Авто чекає</translation>
    </message>
    <message>
        <source>Not ready to arm: %1 of %2 pass</source>
        <translation>Не готовий до ввімкнення: виконано %1 з %2</translation>
    </message>
    <message>
        <source>Not used, Sortie&apos;s default instead: %1</source>
        <translation>Не використано, натомість типовий список Sortie: %1</translation>
    </message>
    <message>
        <source>Sortie&apos;s default; write your own in %1</source>
        <translation>Типовий список Sortie; власний напишіть у %1</translation>
    </message>
    <message>
        <source>Choose a vehicle to see its checklist.</source>
        <translation>Виберіть апарат, щоб побачити його контрольний список.</translation>
    </message>
    <message>
        <source>%1 (advisory)</source>
        <translation>%1 (рекомендація)</translation>
    </message>
    <message>
        <source>Read again</source>
        <translation>Прочитати знову</translation>
    </message>
    <message>
        <source>Read the checklist files again after editing them (the ticks are cleared)</source>
        <translation>Прочитати файли контрольних списків знову після редагування (позначки скидаються)</translation>
    </message>
</context>
<context>
    <name>CommandBar</name>
    <message>
        <source>Are you sure?</source>
        <translation>Ви впевнені?</translation>
    </message>
    <message numerus="yes">
        <source>To %n ticked vehicle(s): %1</source>
        <translation>
            <numerusform>Для %n позначеного апарата: %1</numerusform>
            <numerusform>Для %n позначених апаратів: %1</numerusform>
            <numerusform>Для %n позначених апаратів: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Untick all</source>
        <translation>Зняти всі позначки</translation>
    </message>
    <message>
        <source>Arm</source>
        <translation>Розблокувати</translation>
    </message>
    <message>
        <source>Disarm</source>
        <translation>Заблокувати</translation>
    </message>
    <message>
        <source>Take off</source>
        <translation>Зліт</translation>
    </message>
    <message>
        <source>Climb to %1 m above home</source>
        <translation>Набрати %1 m над точкою дому</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Авто</translation>
    </message>
    <message>
        <source>Fly the uploaded mission</source>
        <translation>Виконати завантажену місію</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Продовжити</translation>
    </message>
    <message>
        <source>Land</source>
        <translation>Посадка</translation>
    </message>
    <message>
        <source>Return home</source>
        <translation>Додому</translation>
    </message>
    <message>
        <source>Go here…</source>
        <translation>Летіти сюди…</translation>
    </message>
    <message>
        <source>Then click on the map where the vehicle should fly</source>
        <translation>Потім клацніть на карті, куди має летіти апарат</translation>
    </message>
    <message>
        <source>Choose a vehicle on the map or in the list; tick several to command them together.</source>
        <translation>Виберіть апарат на карті або в списку; позначте кілька, щоб керувати ними разом.</translation>
    </message>
    <message>
        <source>The checklist does not pass</source>
        <translation>Контрольний список не виконано</translation>
    </message>
    <message>
        <source>%1 is held back on %2 by:</source>
        <translation>%1 для %2 затримано через:</translation>
    </message>
    <message>
        <source>Send it anyway? The override and these reasons go into the command log and the flight log.</source>
        <translation>Надіслати все одно? Обхід і ці причини буде записано в журнал команд і журнал польоту.</translation>
    </message>
    <message>
        <source>Send anyway</source>
        <translation>Надіслати все одно</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Скасувати</translation>
    </message>
    <message>
        <source>Checklist ✓</source>
        <translation>Список ✓</translation>
    </message>
    <message numerus="yes">
        <source>Checklist: %n to do</source>
        <translation>
            <numerusform>Список: %n пункт</numerusform>
            <numerusform>Список: %n пункти</numerusform>
            <numerusform>Список: %n пунктів</numerusform>
        </translation>
    </message>
    <message>
        <source>The pre-flight checklist: Arm and Auto wait for its required items</source>
        <translation>Передпольотний контрольний список: увімкнення двигунів і Авто чекають на його обов’язкові пункти</translation>
    </message>
    <message>
        <source>Gamepad</source>
        <translation>Геймпад</translation>
    </message>
    <message>
        <source>Gamepad buttons as commands, each asking first (by default Start arms, X pauses, Y lands, B returns home). %1</source>
        <translation>Кнопки геймпада як команди, кожна спершу питає (типово Start вмикає двигуни, X — пауза, Y — посадка, B — повернення додому). %1</translation>
    </message>
</context>
<context>
    <name>CommandLogView</name>
    <message>
        <source>Command log</source>
        <translation>Журнал команд</translation>
    </message>
</context>
<context>
    <name>ComparisonPanel</name>
    <message>
        <source>Compare with a route</source>
        <translation>Порівняти з маршрутом</translation>
    </message>
    <message>
        <source>Routes (*.sortie *.plan *.waypoints *.wpl *.txt)</source>
        <translation>Маршрути (*.sortie *.plan *.waypoints *.wpl *.txt)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Усі файли (*)</translation>
    </message>
    <message>
        <source>Compare with route…</source>
        <translation>Порівняти з маршрутом…</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Очистити</translation>
    </message>
    <message>
        <source>leg</source>
        <translation>ділянка</translation>
    </message>
    <message>
        <source>samples</source>
        <translation>відліки</translation>
    </message>
    <message>
        <source>cross-track max</source>
        <translation>бічн. відх. макс</translation>
    </message>
    <message>
        <source>mean</source>
        <translation>середнє</translation>
    </message>
    <message>
        <source>altitude max</source>
        <translation>висота макс</translation>
    </message>
    <message>
        <source>reached</source>
        <translation>досягнуто</translation>
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
        <translation>камера %1 не має розміру сенсора, фокусної відстані чи роздільності</translation>
    </message>
    <message>
        <source>the minimum number of images and the cell must be positive</source>
        <translation>мінімальна кількість знімків і клітинка мають бути додатними</translation>
    </message>
    <message>
        <source>its position is not a place</source>
        <translation>його положення — не місце на Землі</translation>
    </message>
    <message>
        <source>its height above the ground is not known</source>
        <translation>його висота над землею невідома</translation>
    </message>
    <message>
        <source>taken %1 m above the ground: on the ground, not surveying</source>
        <translation>знято на висоті %1 м над землею: на землі, а не під час зйомки</translation>
    </message>
    <message>
        <source>its heading is not known</source>
        <translation>його курс невідомий</translation>
    </message>
    <message>
        <source>no photo has a position, a height above the ground and a heading</source>
        <translation>жоден знімок не має положення, висоти над землею та курсу</translation>
    </message>
    <message>
        <source>PROJ does not know EPSG:%1 (is proj-data installed?)</source>
        <translation>PROJ не знає EPSG:%1 (чи встановлено proj-data?)</translation>
    </message>
    <message>
        <source>no transformation between WGS-84 and EPSG:%1</source>
        <translation>немає перетворення між WGS-84 і EPSG:%1</translation>
    </message>
    <message>
        <source>it cannot be placed in EPSG:%1</source>
        <translation>його не можна розмістити в EPSG:%1</translation>
    </message>
    <message>
        <source>no photo could be placed in EPSG:%1</source>
        <translation>жоден знімок не вдалося розмістити в EPSG:%1</translation>
    </message>
    <message>
        <source>the photos span %1 × %2 m: %3 m cells would make %4 million, more than the %5 million a raster may hold; choose a larger cell</source>
        <translation>знімки охоплюють %1 × %2 м: клітинки по %3 м дали б %4 млн, більше ніж %5 млн, які може вмістити растр; оберіть більшу клітинку</translation>
    </message>
    <message>
        <source>GDAL cannot make a %1 × %2 raster in memory</source>
        <translation>GDAL не може створити растр %1 × %2 у пам&apos;яті</translation>
    </message>
    <message>
        <source>GDAL cannot rasterise the footprints</source>
        <translation>GDAL не може растеризувати відбитки знімків</translation>
    </message>
    <message>
        <source>the photos cover no area</source>
        <translation>знімки не покривають жодної площі</translation>
    </message>
    <message>
        <source>GDAL cannot rasterise the surveyed area</source>
        <translation>GDAL не може растеризувати зняту ділянку</translation>
    </message>
    <message>
        <source>GDAL cannot read its raster back</source>
        <translation>GDAL не може прочитати свій растр назад</translation>
    </message>
    <message>
        <source>GDAL cannot make the holes&apos; layer</source>
        <translation>GDAL не може створити шар прогалин</translation>
    </message>
    <message>
        <source>GDAL cannot trace the holes</source>
        <translation>GDAL не може окреслити прогалини</translation>
    </message>
    <message>
        <source>no raster to write</source>
        <translation>немає растра для запису</translation>
    </message>
    <message>
        <source>GDAL has no GeoTIFF driver</source>
        <translation>GDAL не має драйвера GeoTIFF</translation>
    </message>
    <message>
        <source>%1 cannot be written</source>
        <translation>%1 не вдається записати</translation>
    </message>
    <message>
        <source>%1 cannot be put in place</source>
        <translation>%1 не вдається поставити на місце</translation>
    </message>
    <message>
        <source>Re-fly the gaps</source>
        <translation>Перелетіти прогалини</translation>
    </message>
    <message>
        <source>The hole of %1 m² at %2, %3 is not in the route: %4</source>
        <translation>Прогалини площею %1 м² у %2, %3 немає в маршруті: %4</translation>
    </message>
</context>
<context>
    <name>CoverageSweep</name>
    <message>
        <source>An area scan needs a polygon of at least 3 vertices.</source>
        <translation>Скануванню площі потрібен полігон щонайменше з 3 вершин.</translation>
    </message>
    <message>
        <source>Polygon vertex %1 is not a valid position.</source>
        <translation>Вершина полігона %1 не є коректною позицією.</translation>
    </message>
    <message>
        <source>The polygon spans more than 100 km; split it into smaller scans.</source>
        <translation>Полігон більший за 100 km; розділіть його на менші сканування.</translation>
    </message>
    <message>
        <source>The scan polygon crosses itself (edges %1 and %2).</source>
        <translation>Полігон сканування самоперетинається (ребра %1 і %2).</translation>
    </message>
    <message>
        <source>The scan polygon has no area.</source>
        <translation>Полігон сканування не має площі.</translation>
    </message>
    <message>
        <source>The distance between passes must be positive.</source>
        <translation>Відстань між проходами має бути додатною.</translation>
    </message>
    <message>
        <source>The scan would need %1 transects; raise the altitude or lower the side overlap.</source>
        <translation>Для сканування потрібно проходів: %1; збільште висоту або зменште бічне перекриття.</translation>
    </message>
    <message>
        <source>The scan yields no transects: the polygon is too narrow.</source>
        <translation>Сканування не дає жодного проходу: полігон завузький.</translation>
    </message>
</context>
<context>
    <name>CustomZoneFile</name>
    <message>
        <source>drawn on the map</source>
        <translation>намальовано на карті</translation>
    </message>
</context>
<context>
    <name>DemFolderSource</name>
    <message>
        <source>DEM folder (%1)</source>
        <translation>тека ЦМР (%1)</translation>
    </message>
</context>
<context>
    <name>DemOpener</name>
    <message>
        <source>%1: no such file or folder</source>
        <translation>%1: немає такого файлу чи теки</translation>
    </message>
</context>
<context>
    <name>DemRaster</name>
    <message>
        <source>the raster is not georeferenced (no geotransform)</source>
        <translation>растр не прив’язаний до координат (немає геотрансформації)</translation>
    </message>
    <message>
        <source>the raster states no coordinate reference system</source>
        <translation>растр не вказує системи координат</translation>
    </message>
    <message>
        <source>no transformation from WGS-84 into the raster&apos;s CRS: %1</source>
        <translation>немає перетворення з WGS-84 у систему координат растра: %1</translation>
    </message>
    <message>
        <source>PROJ gave no reason</source>
        <translation>PROJ не вказав причини</translation>
    </message>
    <message>
        <source>the raster&apos;s extent cannot be expressed in WGS-84 degrees</source>
        <translation>охоплення растра не можна виразити в градусах WGS-84</translation>
    </message>
    <message>
        <source>its heights are ellipsoidal and converting them to AMSL needs the EGM96 geoid: %1</source>
        <translation>його висоти еліпсоїдальні, і для перерахунку в AMSL потрібен геоїд EGM96: %1</translation>
    </message>
</context>
<context>
    <name>Egm96Geoid</name>
    <message>
        <source>the EGM96 geoid grid %1 is missing (Debian: install proj-data): ellipsoidal heights cannot be converted to AMSL</source>
        <translation>немає сітки геоїда EGM96 %1 (Debian: встановіть proj-data): еліпсоїдні висоти не можна перерахувати в AMSL</translation>
    </message>
    <message>
        <source>the EGM96 geoid grid %1 cannot be used: %2</source>
        <translation>сітку геоїда EGM96 %1 не можна використати: %2</translation>
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
        <translation>%1 має бути додатним числом</translation>
    </message>
    <message>
        <source>reserve must be a fraction from 0 up to (not including) 1</source>
        <translation>reserve має бути часткою від 0 до 1 (не включно)</translation>
    </message>
    <message>
        <source>acceleration must be a positive number</source>
        <translation>acceleration має бути додатним числом</translation>
    </message>
    <message>
        <source>expected &quot;file&quot;, &quot;server&quot; or &quot;fit&quot;</source>
        <translation>очікується &quot;file&quot;, &quot;server&quot; або &quot;fit&quot;</translation>
    </message>
</context>
<context>
    <name>FleetRoutesList</name>
    <message>
        <source>Routes</source>
        <translation>Маршрути</translation>
    </message>
    <message>
        <source>%1 flight</source>
        <translation>політ: %1</translation>
    </message>
    <message>
        <source>%1 flight · %2 flown · %3 left</source>
        <translation>політ: %1 · пройдено: %2 · лишилося: %3</translation>
    </message>
</context>
<context>
    <name>FlightLogExport</name>
    <message>
        <source>Flight log %1</source>
        <translation>Журнал польоту %1</translation>
    </message>
</context>
<context>
    <name>FlightLogInfo</name>
    <message>
        <source>
  %1 (%2%3%4): %5 samples</source>
        <translation>
  %1 (%2%3%4): відліків: %5</translation>
    </message>
</context>
<context>
    <name>FlightLogSettingsDialog</name>
    <message>
        <source>Flight logs</source>
        <translation>Журнали польотів</translation>
    </message>
    <message>
        <source>Folder</source>
        <translation>Тека</translation>
    </message>
    <message>
        <source>Holds</source>
        <translation>Вміст</translation>
    </message>
    <message>
        <source>Recording to</source>
        <translation>Запис у</translation>
    </message>
    <message>
        <source>not recording</source>
        <translation>запис не ведеться</translation>
    </message>
    <message>
        <source>A log up to (MB)</source>
        <translation>Журнал до (МБ)</translation>
    </message>
    <message>
        <source>The folder up to (MB)</source>
        <translation>Тека до (МБ)</translation>
    </message>
    <message>
        <source>0: no limit. A log over its size continues in a new part; beyond the folder&apos;s size the oldest logs are deleted, never the one being written.</source>
        <translation>0: без обмеження. Журнал, що перевищив розмір, продовжується в новій частині; понад розмір теки видаляються найстаріші журнали, але ніколи не той, що записується.</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Застосувати</translation>
    </message>
</context>
<context>
    <name>GdalDataset</name>
    <message>
        <source>no such file</source>
        <translation>немає такого файлу</translation>
    </message>
    <message>
        <source>GDAL knows no raster format for this file</source>
        <translation>GDAL не знає растрового формату для цього файлу</translation>
    </message>
    <message>
        <source>the file has no raster band</source>
        <translation>файл не має растрового каналу</translation>
    </message>
    <message>
        <source>GeoTIFF (COG), SRTM .hgt, DTED, ESRI ASCII grid, ERDAS Imagine, ESRI .bil/.flt, USGS DEM, PNG, JPEG, JPEG 2000 and .vrt mosaics of them</source>
        <translation>GeoTIFF (COG), SRTM .hgt, DTED, ESRI ASCII grid, ERDAS Imagine, ESRI .bil/.flt, USGS DEM, PNG, JPEG, JPEG 2000 та мозаїки .vrt з них</translation>
    </message>
    <message>
        <source>a GDAL VRT (driver VRT) under a name that is not .vrt: Sortie reads %1</source>
        <translation>GDAL VRT (драйвер VRT) під назвою, що не є .vrt: Sortie читає %1</translation>
    </message>
    <message>
        <source>GDAL reads this file with its %1 driver, which Sortie does not use for the operator&apos;s rasters: it reads %2</source>
        <translation>GDAL читає цей файл своїм драйвером %1, якого Sortie не використовує для растрів оператора: він читає %2</translation>
    </message>
    <message>
        <source>its overview file %1 is not a GeoTIFF (GDAL: %2)</source>
        <translation>його файл оглядів %1 не є GeoTIFF (GDAL: %2)</translation>
    </message>
    <message>
        <source>a raw band (VRTRawRasterBand) is not read</source>
        <translation>сирий канал (VRTRawRasterBand) не читається</translation>
    </message>
    <message>
        <source>a pixel function&apos;s code is not run</source>
        <translation>код піксельної функції не виконується</translation>
    </message>
    <message>
        <source>its source %1 is not a local file</source>
        <translation>його джерело %1 не є локальним файлом</translation>
    </message>
    <message>
        <source>VRTs nested more than %1 deep</source>
        <translation>VRT вкладені глибше ніж на %1 рівні</translation>
    </message>
    <message>
        <source>%1: a VRT of more than %2 MiB</source>
        <translation>%1: VRT понад %2 МіБ</translation>
    </message>
    <message>
        <source>the VRT is not XML</source>
        <translation>VRT не є XML</translation>
    </message>
    <message>
        <source>network access is off: Sortie reads local files only (%1)</source>
        <translation>доступ до мережі вимкнено: Sortie читає лише локальні файли (%1)</translation>
    </message>
</context>
<context>
    <name>GdalDemSource</name>
    <message>
        <source>DEM (%1)</source>
        <translation>ЦМР (%1)</translation>
    </message>
</context>
<context>
    <name>GeoZone</name>
    <message>
        <source>daily</source>
        <translation>щодня</translation>
    </message>
    <message>
        <source>always</source>
        <translation>завжди</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 – %2</translation>
    </message>
    <message>
        <source>from %1</source>
        <translation>з %1</translation>
    </message>
    <message>
        <source>until %1</source>
        <translation>до %1</translation>
    </message>
    <message>
        <source>ask %1 before</source>
        <translation>звертатися за %1 до польоту</translation>
    </message>
    <message>
        <source>Prohibited</source>
        <translation>Заборонено</translation>
    </message>
    <message>
        <source>Authorisation needed</source>
        <translation>Потрібен дозвіл</translation>
    </message>
    <message>
        <source>Conditions apply</source>
        <translation>Діють умови</translation>
    </message>
    <message>
        <source>Information only</source>
        <translation>Лише інформація</translation>
    </message>
</context>
<context>
    <name>Geotag</name>
    <message>
        <source>the track holds no positions</source>
        <translation>трек не містить жодної позиції</translation>
    </message>
    <message>
        <source>taken at %1, %2 s before the track starts (%3)</source>
        <translation>знято о %1, за %2 s до початку треку (%3)</translation>
    </message>
    <message>
        <source>taken at %1, %2 s after the track ends (%3)</source>
        <translation>знято о %1, через %2 s після кінця треку (%3)</translation>
    </message>
    <message>
        <source>taken at %1, in a gap of %2 s in the track (from %3 to %4; at most %5 s is bridged)</source>
        <translation>знято о %1, у розриві треку тривалістю %2 s (від %3 до %4; заповнюється щонайбільше %5 s)</translation>
    </message>
    <message>
        <source>it holds no capture time (EXIF DateTimeOriginal or XMP exif:DateTimeOriginal)</source>
        <translation>у ньому немає часу зйомки (EXIF DateTimeOriginal або XMP exif:DateTimeOriginal)</translation>
    </message>
    <message>
        <source>its copy cannot be made in %1: %2</source>
        <translation>його копію не вдається створити в %1: %2</translation>
    </message>
    <message>
        <source>its copy cannot be put in place: %1</source>
        <translation>його копію не вдається поставити на місце: %1</translation>
    </message>
    <message>
        <source>%1 is not a folder of photos that can be read</source>
        <translation>%1 — не тека з фотографіями, яку можна прочитати</translation>
    </message>
    <message>
        <source>%1 holds no photos (.jpg, .jpeg, .tif, .tiff, .dng)</source>
        <translation>%1 не містить фотографій (.jpg, .jpeg, .tif, .tiff, .dng)</translation>
    </message>
    <message>
        <source>no folder given for the geotagged copies</source>
        <translation>не вказано теку для геотегованих копій</translation>
    </message>
    <message>
        <source>%1: the folder for the geotagged copies cannot be made</source>
        <translation>%1: не вдається створити теку для геотегованих копій</translation>
    </message>
    <message>
        <source>%1 is the photos&apos; own folder: the copies go elsewhere, the originals are never changed</source>
        <translation>%1 — власна тека фотографій: копії зберігаються деінде, оригінали ніколи не змінюються</translation>
    </message>
    <message>
        <source>exiv2 cannot read it (%1)</source>
        <translation>exiv2 не може його прочитати (%1)</translation>
    </message>
    <message>
        <source>exiv2 cannot open it</source>
        <translation>exiv2 не може його відкрити</translation>
    </message>
    <message>
        <source>its OffsetTimeOriginal &quot;%1&quot; is no time zone offset (±HH:MM)</source>
        <translation>його OffsetTimeOriginal «%1» — не зсув часового поясу (±HH:MM)</translation>
    </message>
    <message>
        <source>no valid position to write</source>
        <translation>немає дійсної позиції для запису</translation>
    </message>
    <message>
        <source>exiv2 cannot write its tags (%1)</source>
        <translation>exiv2 не може записати його теги (%1)</translation>
    </message>
    <message>
        <source>%1 is not a GPX file (its root element is &lt;%2&gt;, not &lt;gpx&gt;)</source>
        <translation>%1 — не файл GPX (його кореневий елемент &lt;%2&gt;, а не &lt;gpx&gt;)</translation>
    </message>
    <message>
        <source>%1: a track point needs lat (-90 to 90) and lon (-180 to 180) in degrees, not lat=&quot;%2&quot; lon=&quot;%3&quot;</source>
        <translation>%1: точці треку потрібні lat (від -90 до 90) і lon (від -180 до 180) у градусах, а не lat=&quot;%2&quot; lon=&quot;%3&quot;</translation>
    </message>
    <message>
        <source>%1: &lt;ele&gt; &quot;%2&quot; is no elevation in metres</source>
        <translation>%1: &lt;ele&gt; «%2» — не висота в метрах</translation>
    </message>
    <message>
        <source>%1: &lt;time&gt; &quot;%2&quot; is no UTC time (YYYY-MM-DDThh:mm:ssZ)</source>
        <translation>%1: &lt;time&gt; «%2» — не час UTC (YYYY-MM-DDThh:mm:ssZ)</translation>
    </message>
    <message>
        <source>%1: the track point has no &lt;time&gt;, so no photo can be matched to it</source>
        <translation>%1: точка треку не має &lt;time&gt;, тож до неї не можна прив’язати жодну фотографію</translation>
    </message>
    <message>
        <source>%1 is not a readable GPX file: %2</source>
        <translation>%1 — не придатний для читання файл GPX: %2</translation>
    </message>
    <message>
        <source>%1 is not a GPX file (no &lt;gpx&gt; element)</source>
        <translation>%1 — не файл GPX (немає елемента &lt;gpx&gt;)</translation>
    </message>
    <message>
        <source>%1 holds no track points (&lt;trkpt&gt;)</source>
        <translation>%1 не містить точок треку (&lt;trkpt&gt;)</translation>
    </message>
    <message>
        <source>%1 has no such vehicle</source>
        <translation>%1 не містить такого апарата</translation>
    </message>
    <message>
        <source>%1: vehicle %2 reported no position</source>
        <translation>%1: апарат %2 не повідомив жодної позиції</translation>
    </message>
    <message>
        <source>exiv2 wrote its tags but they do not read back</source>
        <translation>exiv2 записав теги, але не читає їх назад</translation>
    </message>
    <message>
        <source>exiv2 wrote a copy it cannot read back (%1)</source>
        <translation>exiv2 записав копію, яку не може прочитати назад (%1)</translation>
    </message>
    <message>
        <source>no photo the vehicle reported taking matches its time (a shot before or after the flight, or another camera&apos;s)</source>
        <translation>жодне фото, про яке повідомив апарат, не відповідає його часу (знімок до чи після польоту або з іншої камери)</translation>
    </message>
</context>
<context>
    <name>GlanceBar</name>
    <message>
        <source>The connection to the server</source>
        <translation>З&apos;єднання із сервером</translation>
    </message>
    <message>
        <source>The vehicle chosen in the fly view, else the first</source>
        <translation>Апарат, вибраний у вікні польоту, інакше перший</translation>
    </message>
    <message>
        <source>Its GPS: the fix and the satellites in view</source>
        <translation>Його GPS: тип визначення і видимі супутники</translation>
    </message>
    <message>
        <source>Its battery, against the low and critical levels</source>
        <translation>Його акумулятор відносно низького і критичного рівнів</translation>
    </message>
    <message>
        <source>Its link: how often its position arrives</source>
        <translation>Його зв&apos;язок: як часто надходить його позиція</translation>
    </message>
</context>
<context>
    <name>HciConnection</name>
    <message>
        <source>type %1</source>
        <translation>тип %1</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>No answer from %1 within %2: check the address and the network</source>
        <translation>Немає відповіді від %1 протягом %2: перевірте адресу й мережу</translation>
    </message>
    <message>
        <source>The server at %1 closed the connection</source>
        <translation>Сервер %1 закрив з’єднання</translation>
    </message>
    <message>
        <source>The connection was closed by the application</source>
        <translation>З’єднання закрито застосунком</translation>
    </message>
    <message>
        <source>Disconnected from %1</source>
        <translation>Відключено від %1</translation>
    </message>
    <message>
        <source>%1 refused the connection</source>
        <translation>%1 відхилив з’єднання</translation>
    </message>
    <message>
        <source>The host in %1 cannot be found</source>
        <translation>Не вдається знайти хост у %1</translation>
    </message>
    <message>
        <source>Cannot reach %1: %2</source>
        <translation>Не вдається з’єднатися з %1: %2</translation>
    </message>
    <message>
        <source>Connection to %1 lost: %2</source>
        <translation>З’єднання з %1 втрачено: %2</translation>
    </message>
    <message>
        <source>%1 got no answer: %2</source>
        <translation>%1: немає відповіді: %2</translation>
    </message>
    <message>
        <source>%1 is not an HCI message</source>
        <translation>%1 не є повідомленням HCI</translation>
    </message>
    <message>
        <source>%1 not sent: not connected to the server</source>
        <translation>%1 не надіслано: немає підключення до сервера</translation>
    </message>
    <message>
        <source>%1 not sent: missing %2</source>
        <translation>%1 не надіслано: бракує %2</translation>
    </message>
    <message>
        <source>No answer to %1 within %2</source>
        <translation>Немає відповіді на %1 протягом %2</translation>
    </message>
    <message>
        <source>%1 at byte %2: %3</source>
        <translation>%1 на байті %2: %3</translation>
    </message>
    <message>
        <source>%1 with instance id -1 is not a notification</source>
        <translation>%1 з instance id -1 не є сповіщенням</translation>
    </message>
    <message>
        <source>%1 for instance id %2, which no request waits for (answered after its timeout?)</source>
        <translation>%1 для instance id %2, на який не чекає жоден запит (відповідь після тайм-ауту?)</translation>
    </message>
    <message>
        <source>The server answered %1 with %2 instead of %3</source>
        <translation>Сервер відповів на %1 повідомленням %2 замість %3</translation>
    </message>
    <message>
        <source>Not connected to %1 over TLS: %2</source>
        <translation>Немає з’єднання з %1 через TLS: %2</translation>
    </message>
    <message>
        <source>The TLS handshake with %1 failed (%2): does it speak TLS on that port?</source>
        <translation>Рукостискання TLS з %1 не вдалося (%2): чи працює TLS на цьому порту?</translation>
    </message>
    <message>
        <source>%1 accepted the connection but did not begin TLS within %2: is it a plain HCI server?</source>
        <translation>%1 прийняв з’єднання, але не почав TLS протягом %2: чи це незашифрований сервер HCI?</translation>
    </message>
</context>
<context>
    <name>HciElevationSource</name>
    <message>
        <source>UgCS server</source>
        <translation>Сервер UgCS</translation>
    </message>
</context>
<context>
    <name>HciError</name>
    <message>
        <source>The server&apos;s licence does not allow this (%1)</source>
        <translation>Ліцензія сервера цього не дозволяє (%1)</translation>
    </message>
    <message>
        <source>The server&apos;s licence does not allow this</source>
        <translation>Ліцензія сервера цього не дозволяє</translation>
    </message>
    <message>
        <source>The server speaks HCI protocol %1; Sortie speaks 2.0%2</source>
        <translation>Сервер використовує протокол HCI %1; Sortie — 2.0%2</translation>
    </message>
    <message>
        <source>The server refused the request (error %1)</source>
        <translation>Сервер відхилив запит (помилка %1)</translation>
    </message>
    <message>
        <source>The server refused the request without a reason</source>
        <translation>Сервер відхилив запит без пояснення</translation>
    </message>
    <message>
        <source>no error</source>
        <translation>немає помилки</translation>
    </message>
    <message>
        <source> (code %1)</source>
        <translation> (код %1)</translation>
    </message>
</context>
<context>
    <name>HciRouteMapper</name>
    <message>
        <source>Route &quot;%1&quot;, segment %2: %3</source>
        <translation>Маршрут «%1», сегмент %2: %3</translation>
    </message>
</context>
<context>
    <name>HciRoutePass</name>
    <message>
        <source>a RoutePass event names the object type &quot;%1&quot;</source>
        <translation>подія RoutePass називає тип об’єкта «%1»</translation>
    </message>
    <message>
        <source>RoutePass %1: the event carries no RoutePass</source>
        <translation>RoutePass %1: подія не містить RoutePass</translation>
    </message>
    <message>
        <source>RoutePass %1 names no vehicle</source>
        <translation>RoutePass %1 не називає апарата</translation>
    </message>
    <message>
        <source>RoutePass %1 has no waypoint count</source>
        <translation>RoutePass %1 не має кількості точок</translation>
    </message>
    <message>
        <source>RoutePass %1: waypoint index %2 is outside the route&apos;s %3 waypoints</source>
        <translation>RoutePass %1: індекс точки %2 поза межами %3 точок маршруту</translation>
    </message>
</context>
<context>
    <name>HciSegmentMapper</name>
    <message>
        <source>the waypoint has no figure point</source>
        <translation>точка маршруту не має точки фігури</translation>
    </message>
    <message>
        <source>the waypoint&apos;s position is out of range</source>
        <translation>позиція точки маршруту поза допустимими межами</translation>
    </message>
    <message>
        <source>An area scan&apos;s %1: %2 It keeps Sortie&apos;s default.</source>
        <translation>Сканування площі, %1: %2 Залишено типове значення Sortie.</translation>
    </message>
    <message>
        <source>An area scan came without a camera; Sortie&apos;s default camera (%1) was assumed.</source>
        <translation>Сканування площі надійшло без камери; прийнято типову камеру Sortie (%1).</translation>
    </message>
    <message>
        <source>A %1 segment could not be read as one (%2); it is kept as the server sent it.</source>
        <translation>Сегмент %1 не вдалося прочитати як такий (%2); його збережено таким, як надіслав сервер.</translation>
    </message>
    <message>
        <source>An area scan without a polygon of three corners is kept as the server sent it.</source>
        <translation>Сканування площі без полігона з трьох кутів збережено таким, як надіслав сервер.</translation>
    </message>
</context>
<context>
    <name>HciSession</name>
    <message>
        <source> not sent: </source>
        <translation> не надіслано: </translation>
    </message>
    <message>
        <source>the connection to the server is being re-established</source>
        <translation>з’єднання із сервером відновлюється</translation>
    </message>
    <message>
        <source>not logged in to a server</source>
        <translation>немає входу на сервер</translation>
    </message>
    <message>
        <source>The server sent nothing while %1 waited (%2); the link seems dead</source>
        <translation>Сервер нічого не надсилав, поки %1 очікував відповіді (%2); схоже, зв’язок обірвано</translation>
    </message>
    <message>
        <source>The server speaks HCI protocol %1.%2; Sortie speaks %3.%4</source>
        <translation>Сервер використовує протокол HCI %1.%2; Sortie — %3.%4</translation>
    </message>
    <message>
        <source>The server rejected the login &apos;%1&apos;: %2</source>
        <translation>Сервер відхилив вхід «%1»: %2</translation>
    </message>
</context>
<context>
    <name>HciVehicleLink</name>
    <message>
        <source>%1: cannot take control of %2: %3</source>
        <translation>%1: не вдається отримати керування %2: %3</translation>
    </message>
    <message>
        <source>%1: the server sent no result for this vehicle</source>
        <translation>%1: сервер не надіслав результату для цього апарата</translation>
    </message>
    <message>
        <source>there is no such flight mode</source>
        <translation>такого режиму польоту немає</translation>
    </message>
    <message>
        <source>Segment %1: %2</source>
        <translation>Сегмент %1: %2</translation>
    </message>
    <message>
        <source>the server could not process it</source>
        <translation>сервер не зміг це обробити</translation>
    </message>
    <message>
        <source>Sortie upload to %1</source>
        <translation>Завантаження Sortie в %1</translation>
    </message>
    <message>
        <source>route processing: %1</source>
        <translation>обробка маршруту: %1</translation>
    </message>
    <message>
        <source>upload: the mission was not prepared by the UgCS server</source>
        <translation>завантаження: місію не підготовлено сервером UgCS</translation>
    </message>
    <message>
        <source>upload: %1</source>
        <translation>завантаження: %1</translation>
    </message>
    <message>
        <source>upload: cannot take control of %1: %2</source>
        <translation>завантаження: не вдається отримати керування %1: %2</translation>
    </message>
    <message>
        <source>a UgCS server does not read a vehicle&apos;s mission back</source>
        <translation>сервер UgCS не зчитує місію з апарата</translation>
    </message>
    <message>
        <source>%1: parameters are set in the vehicle profile on the UgCS server</source>
        <translation>%1: параметри задаються в профілі апарата на сервері UgCS</translation>
    </message>
</context>
<context>
    <name>HgtTile</name>
    <message>
        <source>%1 bytes is not an SRTM tile (2884802 bytes for 3″ 1201×1201, 25934402 for 1″ 3601×3601); the file is truncated or not a .hgt tile</source>
        <translation>%1 байт — це не тайл SRTM (2884802 байти для 3″ 1201×1201, 25934402 для 1″ 3601×3601); файл обрізаний або не є тайлом .hgt</translation>
    </message>
    <message>
        <source>height %1 m at row %2, column %3 is not a terrain height; the file is corrupt</source>
        <translation>висота %1 m у рядку %2, стовпці %3 не є висотою рельєфу; файл пошкоджено</translation>
    </message>
</context>
<context>
    <name>HgtTileSource</name>
    <message>
        <source>%1: no such file or folder</source>
        <translation>%1: немає такого файлу чи теки</translation>
    </message>
    <message>
        <source>%1: not an SRTM tile name (NxxEyyy.hgt names the tile&apos;s south-west corner)</source>
        <translation>%1: не назва тайла SRTM (NxxEyyy.hgt — це південно-західний кут тайла)</translation>
    </message>
    <message>
        <source>SRTM tiles (%1)</source>
        <translation>Тайли SRTM (%1)</translation>
    </message>
    <message>
        <source>%1: cannot be mapped: %2</source>
        <translation>%1: не вдається відобразити в пам’ять: %2</translation>
    </message>
</context>
<context>
    <name>IndexedDemSource</name>
    <message>
        <source>%1: no rasters</source>
        <translation>%1: немає растрів</translation>
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
        <translation>Апарат не вибрано</translation>
    </message>
    <message>
        <source>Altitude AGL</source>
        <translation>Висота AGL</translation>
    </message>
    <message>
        <source>Altitude AMSL</source>
        <translation>Висота AMSL</translation>
    </message>
    <message>
        <source>Ground speed</source>
        <translation>Шляхова швидкість</translation>
    </message>
    <message>
        <source>Vertical speed</source>
        <translation>Вертикальна швидкість</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Курс</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Батарея</translation>
    </message>
    <message>
        <source>GPS</source>
        <translation>GPS</translation>
    </message>
    <message>
        <source>fix %1, %2 satellites</source>
        <translation>фікс %1, супутників: %2</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Режим</translation>
    </message>
    <message>
        <source>Armed</source>
        <translation>Розблоковано</translation>
    </message>
    <message>
        <source>ARMED</source>
        <translation>РОЗБЛОКОВАНО</translation>
    </message>
    <message>
        <source>disarmed</source>
        <translation>заблоковано</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Зв’язок</translation>
    </message>
    <message>
        <source> (no data)</source>
        <translation> (немає даних)</translation>
    </message>
    <message>
        <source>%1, %2 Hz</source>
        <translation>%1, %2 Hz</translation>
    </message>
    <message>
        <source>Flight time</source>
        <translation>Час польоту</translation>
    </message>
    <message>
        <source>To home</source>
        <translation>До дому</translation>
    </message>
    <message>
        <source>Mission</source>
        <translation>Місія</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Лишилося</translation>
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
        <translation>очікується об’єкт, знайдено %1</translation>
    </message>
    <message>
        <source>missing required key &quot;%1&quot;</source>
        <translation>бракує обов’язкового ключа &quot;%1&quot;</translation>
    </message>
    <message>
        <source>expected an array, found %1</source>
        <translation>очікується масив, знайдено %1</translation>
    </message>
    <message>
        <source>expected at least %1 elements, found %2</source>
        <translation>очікується щонайменше %1 елементів, знайдено %2</translation>
    </message>
    <message>
        <source>expected a number, found %1</source>
        <translation>очікується число, знайдено %1</translation>
    </message>
    <message>
        <source>the number is not finite</source>
        <translation>число не скінченне</translation>
    </message>
    <message>
        <source>expected an integer, found %1</source>
        <translation>очікується ціле число, знайдено %1</translation>
    </message>
    <message>
        <source>expected true or false, found %1</source>
        <translation>очікується true або false, знайдено %1</translation>
    </message>
    <message>
        <source>expected a string, found %1</source>
        <translation>очікується рядок, знайдено %1</translation>
    </message>
    <message>
        <source>not valid JSON: %1</source>
        <translation>некоректний JSON: %1</translation>
    </message>
    <message>
        <source>unknown value &quot;%1&quot;</source>
        <translation>невідоме значення &quot;%1&quot;</translation>
    </message>
</context>
<context>
    <name>KmlFormat</name>
    <message>
        <source>bad coordinate &quot;%1&quot;: expected longitude,latitude[,altitude]</source>
        <translation>хибна координата «%1»: очікується longitude,latitude[,altitude]</translation>
    </message>
    <message>
        <source>bad coordinate &quot;%1&quot;: not a number</source>
        <translation>хибна координата «%1»: не число</translation>
    </message>
    <message>
        <source>coordinate &quot;%1&quot; is out of range</source>
        <translation>координата «%1» поза допустимими межами</translation>
    </message>
    <message>
        <source>a boundary needs at least 3 distinct points, found %1</source>
        <translation>межі потрібно щонайменше 3 різні точки, знайдено %1</translation>
    </message>
    <message>
        <source>not valid KML: %1</source>
        <translation>некоректний KML: %1</translation>
    </message>
    <message>
        <source>this LineString is open, so it encloses no area; close it (last point = first) to use it as a boundary</source>
        <translation>цей LineString незамкнений, тож не охоплює площі; замкніть його (остання точка = перша), щоб використати як межу</translation>
    </message>
    <message>
        <source>this Placemark has no Polygon (with an outerBoundaryIs LinearRing) or closed LineString</source>
        <translation>цей Placemark не має Polygon (з outerBoundaryIs LinearRing) або замкненого LineString</translation>
    </message>
    <message>
        <source>the document has no Polygon or closed LineString</source>
        <translation>документ не має Polygon або замкненого LineString</translation>
    </message>
    <message>
        <source>The file holds %1 closed shapes; the one at line %2 was imported.</source>
        <translation>Файл містить замкнених фігур: %1; імпортовано ту, що в рядку %2.</translation>
    </message>
    <message>
        <source>Flight path</source>
        <translation>Траєкторія польоту</translation>
    </message>
    <message>
        <source>Flight path, part %1</source>
        <translation>Траєкторія польоту, частина %1</translation>
    </message>
</context>
<context>
    <name>KmlZones</name>
    <message>
        <source>bad coordinate &quot;%1&quot;: expected longitude,latitude[,altitude]</source>
        <translation>хибна координата «%1»: очікується longitude,latitude[,altitude]</translation>
    </message>
    <message>
        <source>coordinate &quot;%1&quot; is out of range</source>
        <translation>координата «%1» поза допустимими межами</translation>
    </message>
    <message>
        <source>a boundary needs at least 3 distinct coordinates, found %1</source>
        <translation>межі потрібно щонайменше 3 різні координати, знайдено %1</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>рядок %1: %2</translation>
    </message>
    <message>
        <source>line %1: a polygon with two outer boundaries</source>
        <translation>рядок %1: полігон із двома зовнішніми межами</translation>
    </message>
    <message>
        <source>line %1: an inner boundary before the outer one</source>
        <translation>рядок %1: внутрішня межа перед зовнішньою</translation>
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
        <translation>Polygon без зовнішньої межі</translation>
    </message>
    <message>
        <source>%1 (line %2) was left out: %3</source>
        <translation>%1 (рядок %2) пропущено: %3</translation>
    </message>
    <message>
        <source>not well-formed KML: %1</source>
        <translation>некоректно сформований KML: %1</translation>
    </message>
</context>
<context>
    <name>LandOutlines</name>
    <message>
        <source>the land outline file is not compressed data</source>
        <translation>файл контурів суходолу не є стиснутими даними</translation>
    </message>
    <message>
        <source>the land outline file does not start with %1</source>
        <translation>файл контурів суходолу не починається з %1</translation>
    </message>
    <message>
        <source>the land outline file is truncated at its polygon count</source>
        <translation>файл контурів суходолу обрізано на кількості полігонів</translation>
    </message>
    <message>
        <source>the land outline file is truncated in polygon %1</source>
        <translation>файл контурів суходолу обрізано в полігоні %1</translation>
    </message>
    <message>
        <source>the land outline file is truncated in polygon %1, ring %2</source>
        <translation>файл контурів суходолу обрізано в полігоні %1, контур %2</translation>
    </message>
    <message>
        <source>the built-in land outlines (%1) are missing</source>
        <translation>вбудованих контурів суходолу (%1) немає</translation>
    </message>
</context>
<context>
    <name>LoginPage</name>
    <message>
        <source>Connect to a UgCS server</source>
        <translation>Підключення до сервера UgCS</translation>
    </message>
    <message>
        <source>Server (host:port)</source>
        <translation>Сервер (host:port)</translation>
    </message>
    <message>
        <source>Host name or address and HCI port of the UgCS server</source>
        <translation>Ім’я або адреса хоста та порт HCI сервера UgCS</translation>
    </message>
    <message>
        <source>User</source>
        <translation>Користувач</translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Пароль</translation>
    </message>
    <message>
        <source>Remember the password on this computer</source>
        <translation>Запам’ятати пароль на цьому комп’ютері</translation>
    </message>
    <message>
        <source>Kept in this computer&apos;s keyring for this server and user, never in a file</source>
        <translation>Зберігається в сховищі паролів цього комп’ютера для цього сервера й користувача, ніколи не у файлі</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Підключитися</translation>
    </message>
    <message>
        <source>Log in (Enter in the password field)</source>
        <translation>Увійти (Enter у полі пароля)</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Відключитися</translation>
    </message>
    <message>
        <source>Logged in as %1 at %2.</source>
        <translation>Ви увійшли як %1 на %2.</translation>
    </message>
    <message>
        <source>%1…</source>
        <translation>%1…</translation>
    </message>
    <message>
        <source>Secure (TLS)</source>
        <translation>Захищено (TLS)</translation>
    </message>
    <message>
        <source>For a server behind a TLS terminator: the password and everything else travel encrypted</source>
        <translation>Для сервера за TLS-термінатором: пароль і все інше передаються зашифрованими</translation>
    </message>
    <message>
        <source>Send in clear</source>
        <translation>Надіслати незашифрованим</translation>
    </message>
    <message>
        <source>Do not connect</source>
        <translation>Не підключатися</translation>
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
        <translation>Вхід</translation>
    </message>
    <message>
        <source>Mission</source>
        <translation>Місія</translation>
    </message>
    <message>
        <source>Live telemetry</source>
        <translation>Телеметрія</translation>
    </message>
    <message>
        <source>Map…</source>
        <translation>Карта…</translation>
    </message>
    <message>
        <source>Choose the map source (Ctrl+M)</source>
        <translation>Вибрати джерело карти (Ctrl+M)</translation>
    </message>
    <message>
        <source>Offline…</source>
        <translation>Офлайн…</translation>
    </message>
    <message>
        <source>Download the web map of an area for work without a network</source>
        <translation>Завантажити веб-карту району для роботи без мережі</translation>
    </message>
    <message>
        <source>Logs…</source>
        <translation>Журнали…</translation>
    </message>
    <message>
        <source>Where flight logs are recorded, and how much they may take</source>
        <translation>Куди записуються журнали польотів і скільки місця вони можуть займати</translation>
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
        <translation>Перемкнути метричні та імперські одиниці</translation>
    </message>
    <message>
        <source>Keyboard shortcuts (F1)</source>
        <translation>Гарячі клавіші (F1)</translation>
    </message>
    <message>
        <source>The language of Sortie, applied at once</source>
        <translation>Мова Sortie, застосовується одразу</translation>
    </message>
    <message>
        <source>Display…</source>
        <translation>Вигляд…</translation>
    </message>
    <message>
        <source>Units, language and colours</source>
        <translation>Одиниці, мова і кольори</translation>
    </message>
    <message>
        <source>Units</source>
        <translation>Одиниці</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Мова</translation>
    </message>
    <message>
        <source>Colours</source>
        <translation>Кольори</translation>
    </message>
    <message>
        <source>The system&apos;s colours, light, dark, or high contrast for sunlight</source>
        <translation>Кольори системи, світлі, темні або висока контрастність для сонячного світла</translation>
    </message>
</context>
<context>
    <name>MapPane</name>
    <message>
        <source>Zoom in (+, wheel)</source>
        <translation>Наблизити (+, коліщатко)</translation>
    </message>
    <message>
        <source>Zoom out (−, wheel)</source>
        <translation>Віддалити (−, коліщатко)</translation>
    </message>
</context>
<context>
    <name>MapSourceDialog</name>
    <message>
        <source>Map source</source>
        <translation>Джерело карти</translation>
    </message>
    <message>
        <source>Offline base map (land outlines, always available)</source>
        <translation>Офлайн-базова карта (контури суходолу, завжди доступна)</translation>
    </message>
    <message>
        <source>Web tiles from a URL template</source>
        <translation>Веб-тайли за шаблоном URL</translation>
    </message>
    <message>
        <source>{z}, {x} and {y} (or {-y}) are replaced per tile; {s} by a subdomain</source>
        <translation>{z}, {x} і {y} (або {-y}) підставляються для кожного тайла; {s} — піддомен</translation>
    </message>
    <message>
        <source>MBTiles file (offline raster tiles)</source>
        <translation>Файл MBTiles (офлайн растрові тайли)</translation>
    </message>
    <message>
        <source>/path/to/area.mbtiles</source>
        <translation>/шлях/до/району.mbtiles</translation>
    </message>
    <message>
        <source>Orthophoto over the base map (GeoTIFF or any raster GDAL reads, any CRS)</source>
        <translation>Ортофотоплан поверх базової карти (GeoTIFF або будь-який растр, який читає GDAL, будь-яка CRS)</translation>
    </message>
    <message>
        <source>/path/to/orthophoto.tif (empty: none)</source>
        <translation>/шлях/до/ортофото.tif (порожньо: немає)</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Непрозорість</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Terrain: a DEM file (GeoTIFF, .hgt, ...) or a folder of them</source>
        <translation>Рельєф: файл DEM (GeoTIFF, .hgt, ...) або тека з ними</translation>
    </message>
    <message>
        <source>/path/to/dem.tif or /path/to/dem-folder (empty: none)</source>
        <translation>/шлях/до/dem.tif або /шлях/до/теки-dem (порожньо: немає)</translation>
    </message>
    <message>
        <source>Orthophoto</source>
        <translation>Ортофотоплан</translation>
    </message>
    <message>
        <source>Rasters (*.tif *.tiff *.jp2 *.vrt *.img *.ecw *.sid *.png *.jpg)</source>
        <translation>Растри (*.tif *.tiff *.jp2 *.vrt *.img *.ecw *.sid *.png *.jpg)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Усі файли (*)</translation>
    </message>
    <message>
        <source>Terrain model (DEM)</source>
        <translation>Модель рельєфу (DEM)</translation>
    </message>
    <message>
        <source>Elevation rasters (*.tif *.tiff *.hgt *.vrt *.dt0 *.dt1 *.dt2 *.asc *.img *.bil *.flt *.dem)</source>
        <translation>Растри висот (*.tif *.tiff *.hgt *.vrt *.dt0 *.dt1 *.dt2 *.asc *.img *.bil *.flt *.dem)</translation>
    </message>
    <message>
        <source>A folder of terrain models (DEM tiles)</source>
        <translation>Тека з моделями рельєфу (тайли DEM)</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Огляд…</translation>
    </message>
    <message>
        <source>File…</source>
        <translation>Файл…</translation>
    </message>
    <message>
        <source>Folder…</source>
        <translation>Тека…</translation>
    </message>
</context>
<context>
    <name>MavlinkExport</name>
    <message>
        <source>MAVLink has no stop-and-turn or bank-turn waypoints: they were written as plain waypoints.</source>
        <translation>MAVLink не має точок «зупинка й поворот» чи «поворот із креном»: їх записано як звичайні точки.</translation>
    </message>
    <message>
        <source>Waypoint %1: %2 has no MAVLink equivalent and was left out.</source>
        <translation>Точка %1: %2 не має відповідника в MAVLink, пропущено.</translation>
    </message>
    <message>
        <source>a servo action without its servo and PWM</source>
        <translation>дія сервопривода без сервопривода і PWM</translation>
    </message>
    <message>
        <source>a repeated servo without its count and cycle time</source>
        <translation>повтор сервопривода без кількості й періоду циклу</translation>
    </message>
    <message>
        <source>waiting for the operator</source>
        <translation>очікування оператора</translation>
    </message>
    <message>
        <source>a heading relative to the course</source>
        <translation>курс відносно напрямку руху</translation>
    </message>
    <message>
        <source>toggling video</source>
        <translation>перемикання відео</translation>
    </message>
    <message>
        <source>the series&apos; start delay</source>
        <translation>затримка початку серії</translation>
    </message>
    <message>
        <source>the series&apos; shot count and start delay</source>
        <translation>кількість знімків і затримка початку серії</translation>
    </message>
    <message>
        <source>a panorama</source>
        <translation>панорама</translation>
    </message>
    <message>
        <source>Waypoint %1: the gimbal&apos;s %2 was not set and is written as 0° (MAVLink has no &quot;unchanged&quot;).</source>
        <translation>Точка %1: %2 підвісу не задано, записано 0° (у MAVLink немає «без змін»).</translation>
    </message>
    <message>
        <source>a zoom level</source>
        <translation>рівень зуму</translation>
    </message>
    <message>
        <source>%1 was left out: %2</source>
        <translation>%1 пропущено: %2</translation>
    </message>
    <message>
        <source>it cannot be planned</source>
        <translation>його не можна спланувати</translation>
    </message>
    <message>
        <source>Segments without a MAVLink equivalent (circle, perimeter...) were written as the waypoints Sortie plans for them.</source>
        <translation>Сегменти без відповідника в MAVLink (коло, периметр...) записано як точки, які для них планує Sortie.</translation>
    </message>
    <message>
        <source>Area scan %1 was left out: %2</source>
        <translation>Сканування площі %1 пропущено: %2</translation>
    </message>
    <message>
        <source>Area scan %1 was written as %2 waypoints with distance triggering.</source>
        <translation>Сканування площі %1 записано як точки (%2) зі спуском затвора за відстанню.</translation>
    </message>
    <message>
        <source>tilt</source>
        <extracomment>A gimbal&apos;s axis, listed in &quot;the gimbal&apos;s %2 was not set&quot; (tilt, roll, yaw).</extracomment>
        <translation>нахил</translation>
    </message>
    <message>
        <source>roll</source>
        <extracomment>A gimbal&apos;s axis, listed in &quot;the gimbal&apos;s %2 was not set&quot; (tilt, roll, yaw).</extracomment>
        <translation>крен</translation>
    </message>
    <message>
        <source>yaw</source>
        <extracomment>A gimbal&apos;s axis, listed in &quot;the gimbal&apos;s %2 was not set&quot; (tilt, roll, yaw).</extracomment>
        <translation>рискання</translation>
    </message>
</context>
<context>
    <name>MbTilesFile</name>
    <message>
        <source>No MBTiles file is set.</source>
        <translation>Файл MBTiles не задано.</translation>
    </message>
    <message>
        <source>The MBTiles file %1 does not exist.</source>
        <translation>Файл MBTiles %1 не існує.</translation>
    </message>
    <message>
        <source>Cannot open the MBTiles file %1: %2</source>
        <translation>Не вдається відкрити файл MBTiles %1: %2</translation>
    </message>
    <message>
        <source>%1 is not an MBTiles file Sortie can write: %2</source>
        <translation>%1 не є файлом MBTiles, у який Sortie може записувати: %2</translation>
    </message>
    <message>
        <source>%1 is not an MBTiles file (it has no tiles table).</source>
        <translation>%1 не є файлом MBTiles (немає таблиці tiles).</translation>
    </message>
    <message>
        <source>The MBTiles file %1 has no readable metadata: %2</source>
        <translation>Файл MBTiles %1 не має придатних для читання метаданих: %2</translation>
    </message>
    <message>
        <source>Cannot write to the MBTiles file %1: %2</source>
        <translation>Не вдається записати у файл MBTiles %1: %2</translation>
    </message>
    <message>
        <source>Cannot write the metadata of %1: %2</source>
        <translation>Не вдається записати метадані %1: %2</translation>
    </message>
    <message>
        <source>Reading tile %1 failed: %2</source>
        <translation>Не вдалося прочитати тайл %1: %2</translation>
    </message>
    <message>
        <source>Writing %1 tiles to %2 failed: %3</source>
        <translation>Не вдалося записати тайли (кількість: %1) у %2: %3</translation>
    </message>
    <message>
        <source>Reading the tiles of %1 failed: %2</source>
        <translation>Не вдалося прочитати тайли %1: %2</translation>
    </message>
    <message>
        <source>The MBTiles file %1 has more than %2 metadata rows.</source>
        <translation>Файл MBTiles %1 має понад %2 рядків метаданих.</translation>
    </message>
    <message>
        <source>stopped: %1</source>
        <translation>зупинено: %1</translation>
    </message>
</context>
<context>
    <name>MbTilesMetadata</name>
    <message>
        <source>%1: &apos;%2&apos; is not a zoom level (0 to 30).</source>
        <translation>%1: «%2» не є рівнем масштабу (від 0 до 30).</translation>
    </message>
    <message>
        <source>bounds: &apos;%1&apos; is not west,south,east,north in degrees.</source>
        <translation>bounds: «%1» не є west,south,east,north у градусах.</translation>
    </message>
    <message>
        <source>minzoom %1 is above maxzoom %2.</source>
        <translation>minzoom %1 більший за maxzoom %2.</translation>
    </message>
</context>
<context>
    <name>MissionDifference</name>
    <message numerus="yes">
        <source>the vehicle holds %n waypoint(s), %1 were sent</source>
        <translation>
            <numerusform>на борту апарата %n точка, надіслано %1</numerusform>
            <numerusform>на борту апарата %n точки, надіслано %1</numerusform>
            <numerusform>на борту апарата %n точок, надіслано %1</numerusform>
        </translation>
    </message>
    <message>
        <source>waypoint %1: </source>
        <translation>точка %1: </translation>
    </message>
    <message>
        <source>the vehicle holds another position</source>
        <translation>на борту апарата інша позиція</translation>
    </message>
    <message>
        <source>altitude %1 m, sent %2 m</source>
        <translation>висота %1 m, надіслано %2 m</translation>
    </message>
    <message>
        <source>speed %1 m/s, sent %2 m/s</source>
        <translation>швидкість %1 m/s, надіслано %2 m/s</translation>
    </message>
    <message>
        <source>acceptance radius %1 m, sent %2 m</source>
        <translation>радіус досягнення %1 m, надіслано %2 m</translation>
    </message>
    <message numerus="yes">
        <source>%n action(s), sent %1</source>
        <translation>
            <numerusform>%n дія, надіслано %1</numerusform>
            <numerusform>%n дії, надіслано %1</numerusform>
            <numerusform>%n дій, надіслано %1</numerusform>
        </translation>
    </message>
    <message>
        <source>action %1 (%2) differs</source>
        <translation>дія %1 (%2) відрізняється</translation>
    </message>
</context>
<context>
    <name>MissionError</name>
    <message>
        <source>(at %1)</source>
        <translation>(у %1)</translation>
    </message>
</context>
<context>
    <name>MissionFiles</name>
    <message>
        <source>cannot open: %1</source>
        <translation>не вдається відкрити: %1</translation>
    </message>
    <message>
        <source>unknown file type: use .sortie, .plan, .waypoints, .kml or .kmz</source>
        <translation>невідомий тип файлу: використовуйте .sortie, .plan, .waypoints, .kml або .kmz</translation>
    </message>
    <message>
        <source>Sortie mission</source>
        <translation>Місія Sortie</translation>
    </message>
    <message>
        <source>QGroundControl plan</source>
        <translation>План QGroundControl</translation>
    </message>
    <message>
        <source>QGC WPL 110 waypoints</source>
        <translation>Точки QGC WPL 110</translation>
    </message>
    <message>
        <source>DJI WPML</source>
        <translation>DJI WPML</translation>
    </message>
    <message>
        <source>a KML file holds a polygon, not a mission: import it as an area-scan boundary</source>
        <translation>файл KML містить полігон, а не місію: імпортуйте його як межу сканування площі</translation>
    </message>
    <message>
        <source>the mission has no route %1 (it has %2)</source>
        <translation>місія не має маршруту %1 (маршрутів у ній: %2)</translation>
    </message>
    <message>
        <source>the mission has no route to write</source>
        <translation>місія не має маршруту для запису</translation>
    </message>
    <message>
        <source>the mission has %1 routes and a %2 file holds one: choose the route to write (sortie-plan convert --route N), or write .sortie or DJI WPML (.kmz), which hold them all</source>
        <translation>місія має маршрутів: %1, а файл %2 містить один: виберіть маршрут для запису (sortie-plan convert --route N) або запишіть .sortie чи DJI WPML (.kmz), які містять усі</translation>
    </message>
    <message>
        <source>Saving route &quot;%1&quot;</source>
        <translation>Збереження маршруту «%1»</translation>
    </message>
    <message>
        <source>cannot write: %1</source>
        <translation>не вдається записати: %1</translation>
    </message>
    <message>
        <source>the file is larger than %1 MiB</source>
        <translation>файл більший за %1 МіБ</translation>
    </message>
</context>
<context>
    <name>MissionPage</name>
    <message>
        <source>Zones (%1)</source>
        <translation>Зони (%1)</translation>
    </message>
    <message>
        <source>Click the centre line (%1 so far)</source>
        <translation>Клацніть осьову лінію (поки що %1)</translation>
    </message>
    <message>
        <source>Click the corners of the area (%1 so far)</source>
        <translation>Клацніть кути району (поки що %1)</translation>
    </message>
    <message>
        <source>Click where it goes</source>
        <translation>Клацніть місце розміщення</translation>
    </message>
    <message>
        <source>Create</source>
        <translation>Створити</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Скасувати</translation>
    </message>
    <message>
        <source>Click the corners (%1 so far), or Shift+drag a box</source>
        <translation>Клацніть кути (поки %1) або протягніть прямокутник із Shift</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Готово</translation>
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
        <translation>Назад до карти</translation>
    </message>
    <message>
        <source>The route, the ground and the zones in 3D</source>
        <translation>Маршрут, рельєф і зони в 3D</translation>
    </message>
</context>
<context>
    <name>NfzConversion</name>
    <message>
        <source>its baseAltitude is not a number</source>
        <translation>її baseAltitude не є числом</translation>
    </message>
    <message>
        <source>its height %1 m is not a height (it must be 0 or more)</source>
        <translation>її висота %1 m не є висотою (має бути 0 або більше)</translation>
    </message>
    <message>
        <source>point %1 of its prism is not a position (latitude and longitude in radians)</source>
        <translation>точка %1 її призми не є позицією (широта й довгота в радіанах)</translation>
    </message>
    <message numerus="yes">
        <source>its prism has %n corner(s); a polygon needs 3</source>
        <translation>
            <numerusform>її призма має %n кут; полігону потрібно 3</numerusform>
            <numerusform>її призма має %n кути; полігону потрібно 3</numerusform>
            <numerusform>її призма має %n кутів; полігону потрібно 3</numerusform>
        </translation>
    </message>
    <message>
        <source>its cone frustum has no centre (baseLatitude, baseLongitude in radians)</source>
        <translation>її зрізаний конус не має центру (baseLatitude, baseLongitude у радіанах)</translation>
    </message>
    <message>
        <source>its cone frustum&apos;s radii (base %1 m, top %2 m) are not a circle</source>
        <translation>радіуси її зрізаного конуса (основа %1 m, верх %2 m) не утворюють кола</translation>
    </message>
    <message>
        <source>its cone frustum has two radii but no height</source>
        <translation>її зрізаний конус має два радіуси, але не має висоти</translation>
    </message>
    <message>
        <source>its floor (%1) and ceiling (%2) are in different references; a server zone has one</source>
        <translation>її нижня (%1) і верхня (%2) межі задано в різних системах відліку; у зони сервера вона одна</translation>
    </message>
    <message>
        <source>its heights are above home; a server zone&apos;s are AMSL or AGL</source>
        <translation>її висоти задано відносно дому; у зони сервера вони AMSL або AGL</translation>
    </message>
    <message>
        <source>it starts from the ground with an AMSL ceiling; give it an AMSL floor or an AGL ceiling</source>
        <translation>вона починається від поверхні з верхньою межею AMSL; задайте нижню межу AMSL або верхню межу AGL</translation>
    </message>
    <message>
        <source>NoFlightZone %1</source>
        <translation>NoFlightZone %1</translation>
    </message>
    <message>
        <source>UgCS server, NoFlightZone %1</source>
        <translation>Сервер UgCS, NoFlightZone %1</translation>
    </message>
    <message>
        <source>it has both a prism and a cone frustum</source>
        <translation>вона має і призму, і зрізаний конус</translation>
    </message>
    <message>
        <source>it has no volume (neither a prism nor a cone frustum)</source>
        <translation>вона не має об’єму (ні призми, ні зрізаного конуса)</translation>
    </message>
    <message>
        <source>its ceiling is below its floor</source>
        <translation>її верхня межа нижче за нижню</translation>
    </message>
    <message>
        <source>the server&apos;s no-fly zones keep vehicles out; an inclusion zone cannot be one</source>
        <translation>заборонені зони сервера не пускають апарати всередину; дозвільна зона не може бути такою</translation>
    </message>
    <message>
        <source>aerodrome zones are the server&apos;s own; only custom zones are changed</source>
        <translation>зони аеродромів належать серверу; змінюються лише власні зони</translation>
    </message>
    <message numerus="yes">
        <source>%n ring(s)</source>
        <translation>
            <numerusform>%n контур</numerusform>
            <numerusform>%n контури</numerusform>
            <numerusform>%n контурів</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>a server zone is one polygon without holes (this one has %n part(s), %1)</source>
        <translation>
            <numerusform>зона сервера — це один полігон без отворів (ця має %n частину, %1)</numerusform>
            <numerusform>зона сервера — це один полігон без отворів (ця має %n частини, %1)</numerusform>
            <numerusform>зона сервера — це один полігон без отворів (ця має %n частин, %1)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>its polygon has %n corner(s); it needs 3</source>
        <translation>
            <numerusform>її полігон має %n кут; потрібно 3</numerusform>
            <numerusform>її полігон має %n кути; потрібно 3</numerusform>
            <numerusform>її полігон має %n кутів; потрібно 3</numerusform>
        </translation>
    </message>
    <message>
        <source>a cone frustum needs a ceiling</source>
        <translation>зрізаному конусу потрібна верхня межа</translation>
    </message>
    <message>
        <source>NoFlightZone %1%2 was left out: %3</source>
        <translation>NoFlightZone %1%2 пропущено: %3</translation>
    </message>
</context>
<context>
    <name>NumberField</name>
    <message>
        <source>Not a number: type it as %1</source>
        <translation>Не число: введіть його як %1</translation>
    </message>
    <message>
        <source>From %1 to %2</source>
        <translation>Від %1 до %2</translation>
    </message>
    <message>
        <source>At least %1</source>
        <translation>Щонайменше %1</translation>
    </message>
    <message>
        <source>At most %1</source>
        <translation>Щонайбільше %1</translation>
    </message>
</context>
<context>
    <name>OfflineMapsDialog</name>
    <message>
        <source>Offline maps</source>
        <translation>Офлайн-карти</translation>
    </message>
    <message>
        <source>From %1</source>
        <translation>З %1</translation>
    </message>
    <message>
        <source>Choose a web tile server in Map source first.</source>
        <translation>Спочатку виберіть веб-сервер тайлів у «Джерело карти».</translation>
    </message>
    <message>
        <source>The open route</source>
        <translation>Відкритий маршрут</translation>
    </message>
    <message>
        <source>and</source>
        <translation>і</translation>
    </message>
    <message>
        <source>m around it</source>
        <translation>m навколо нього</translation>
    </message>
    <message>
        <source>The map&apos;s view</source>
        <translation>Видима область карти</translation>
    </message>
    <message>
        <source>Zoom from</source>
        <translation>Масштаб від</translation>
    </message>
    <message>
        <source>to</source>
        <translation>до</translation>
    </message>
    <message>
        <source>Pack file</source>
        <translation>Файл пакета</translation>
    </message>
    <message>
        <source>Attribution</source>
        <translation>Атрибуція</translation>
    </message>
    <message>
        <source>As the provider&apos;s usage policy asks, e.g. © OpenStreetMap contributors</source>
        <translation>Як вимагають правила постачальника, напр. © OpenStreetMap contributors</translation>
    </message>
    <message>
        <source>Cache only: the map never uses the network (the pack, then the disk cache)</source>
        <translation>Лише кеш: карта ніколи не використовує мережу (пакет, потім дисковий кеш)</translation>
    </message>
    <message>
        <source>Download</source>
        <translation>Завантажити</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Продовжити</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Зупинити</translation>
    </message>
    <message>
        <source>Draw an area</source>
        <translation>Намалювати область</translation>
    </message>
    <message>
        <source>Click its corners on the map, or Shift+drag a box</source>
        <translation>Клацніть її кути на мапі або протягніть прямокутник із Shift</translation>
    </message>
</context>
<context>
    <name>OpenQuestion</name>
    <message>
        <source>Unsaved edits</source>
        <translation>Незбережені зміни</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Зберегти</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Відкинути</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Скасувати</translation>
    </message>
</context>
<context>
    <name>OrthophotoRenderer</name>
    <message>
        <source>the image is not georeferenced (no CRS or no geotransform)</source>
        <translation>зображення не прив’язане до координат (немає системи координат або геотрансформації)</translation>
    </message>
    <message>
        <source>its extent cannot be placed on the map: %1</source>
        <translation>його охоплення не можна розмістити на карті: %1</translation>
    </message>
    <message>
        <source>PROJ gave no reason</source>
        <translation>PROJ не вказав причини</translation>
    </message>
    <message>
        <source>no memory for a tile</source>
        <translation>немає пам’яті для тайла</translation>
    </message>
    <message>
        <source>%1: tile %2/%3/%4: %5</source>
        <translation>%1: тайл %2/%3/%4: %5</translation>
    </message>
    <message>
        <source>the warp failed</source>
        <translation>перепроєкціювання не вдалося</translation>
    </message>
    <message>
        <source>the warped tile cannot be read</source>
        <translation>перепроєкційований тайл не можна прочитати</translation>
    </message>
    <message>
        <source>%1: tile size %2 is outside 1..%3</source>
        <translation>%1: розмір тайла %2 поза межами 1..%3</translation>
    </message>
</context>
<context>
    <name>OutsideDatabase</name>
    <message>
        <source>more than %1 steps</source>
        <translation>понад %1 кроків</translation>
    </message>
    <message>
        <source>more than %1 rows</source>
        <translation>понад %1 рядків</translation>
    </message>
    <message>
        <source>SQLite refused the settings a file from outside is read with</source>
        <translation>SQLite відхилив налаштування, з якими читається файл ззовні</translation>
    </message>
</context>
<context>
    <name>PhotosDialog</name>
    <message>
        <source>Photos of the flight</source>
        <translation>Знімки польоту</translation>
    </message>
    <message>
        <source>The folder of the flight&apos;s photos</source>
        <translation>Тека зі знімками польоту</translation>
    </message>
    <message>
        <source>Where the geotagged copies go</source>
        <translation>Куди покласти копії з геопозицією</translation>
    </message>
    <message>
        <source>Photos</source>
        <translation>Знімки</translation>
    </message>
    <message>
        <source>a folder of JPEG, TIFF or DNG photos</source>
        <translation>тека зі знімками JPEG, TIFF або DNG</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Вибрати…</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Камера</translation>
    </message>
    <message>
        <source>Camera clock behind the log (s)</source>
        <translation>Годинник камери позаду журналу (с)</translation>
    </message>
    <message>
        <source>Seconds added to each photo&apos;s time: how far the camera&apos;s clock is behind the log&apos;s (GNSS) time</source>
        <translation>Секунди, що додаються до часу кожного знімка: наскільки годинник камери відстає від часу журналу (GNSS)</translation>
    </message>
    <message>
        <source>Place photos</source>
        <translation>Розмістити знімки</translation>
    </message>
    <message>
        <source>Holes, largest first (shaded on the map):</source>
        <translation>Прогалини, найбільша перша (заштриховані на мапі):</translation>
    </message>
    <message>
        <source>Not placed:</source>
        <translation>Не розміщено:</translation>
    </message>
    <message>
        <source>Write geotagged copies…</source>
        <translation>Записати копії з геопозицією…</translation>
    </message>
    <message>
        <source>Re-fly the gaps</source>
        <translation>Перелетіти прогалини</translation>
    </message>
    <message>
        <source>A route of an area scan per hole, with the survey&apos;s camera, height and overlap, opened in the mission editor</source>
        <translation>Маршрут зі зйомкою площі на кожну прогалину, з камерою, висотою й перекриттям зйомки, відкритий у редакторі місій</translation>
    </message>
</context>
<context>
    <name>PrivateFiles</name>
    <message>
        <source>Cannot create the folder %1: %2 is not a folder</source>
        <translation>Не вдається створити теку %1: %2 не є текою</translation>
    </message>
    <message>
        <source>Cannot create the folder %1: %2</source>
        <translation>Не вдається створити теку %1: %2</translation>
    </message>
    <message>
        <source>Cannot create the folder %1</source>
        <translation>Не вдається створити теку %1</translation>
    </message>
    <message>
        <source>Cannot create %1: %2</source>
        <translation>Не вдається створити %1: %2</translation>
    </message>
    <message>
        <source>Cannot create a private folder in %1: %2</source>
        <translation>Не вдається створити приватну теку в %1: %2</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source> in %1 s</source>
        <translation> через %1 s</translation>
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
        <translation>пропущено</translation>
    </message>
    <message>
        <source>That vehicle is not in this log (it holds %1).</source>
        <translation>Цього апарата немає в журналі (у ньому: %1).</translation>
    </message>
    <message>
        <source>no vehicle</source>
        <translation>немає апарата</translation>
    </message>
    <message>
        <source>Route &quot;%1&quot; has fewer than two waypoints: there is nothing to compare.</source>
        <translation>Маршрут «%1» має менше двох точок: немає чого порівнювати.</translation>
    </message>
    <message>
        <source>%1 has no track in this log to compare with.</source>
        <translation>%1 не має треку в цьому журналі для порівняння.</translation>
    </message>
    <message>
        <source>Route &quot;%1&quot; does not match %2: its waypoints are %3 km from anywhere %2 flew in this log.</source>
        <translation>Маршрут «%1» не відповідає %2: його точки за %3 km від будь-якого місця, де %2 літав у цьому журналі.</translation>
    </message>
    <message>
        <source>%1 flown by %2, %3 to %4
</source>
        <translation>%1, виконав %2, з %3 до %4
</translation>
    </message>
    <message>
        <source>
waypoint  reached                    closest
</source>
        <translation>
   точка  досягнуто                  найближче
</translation>
    </message>
    <message>
        <source>
leg      samples  cross-track max  mean      altitude max  mean
</source>
        <translation>
ділянка  відліки  бічн.відх.макс  середнє   висота макс   середнє
</translation>
    </message>
    <message>
        <source>
total: %1 reached, %2 missed; cross-track max %3, mean %4; altitude max %5, mean %6
</source>
        <translation>
разом: досягнуто %1, пропущено %2; бічне відхилення макс %3, середнє %4; висота макс %5, середня %6
</translation>
    </message>
    <message>
        <source>%1: no such file</source>
        <translation>%1: файлу не існує</translation>
    </message>
    <message>
        <source>%1: cannot be opened: %2</source>
        <translation>%1: не вдається відкрити: %2</translation>
    </message>
    <message>
        <source>no Sortie flight log header</source>
        <translation>немає заголовка журналу польоту Sortie</translation>
    </message>
    <message>
        <source>%1 is not a Sortie flight log (%2)</source>
        <translation>%1 не є журналом польоту Sortie (%2)</translation>
    </message>
    <message>
        <source>%1: the vehicles cannot be read: %2</source>
        <translation>%1: не вдається прочитати апарати: %2</translation>
    </message>
    <message>
        <source>the vehicle list is damaged: %1</source>
        <translation>список апаратів пошкоджено: %1</translation>
    </message>
    <message>
        <source>unknown vehicle</source>
        <translation>невідомий апарат</translation>
    </message>
    <message>
        <source>stopped after %1 good blocks (%2): %3</source>
        <translation>зупинено після %1 цілих блоків (%2): %3</translation>
    </message>
    <message>
        <source>none</source>
        <translation>немає</translation>
    </message>
    <message>
        <source>the telemetry cannot be read: %1</source>
        <translation>не вдається прочитати телеметрію: %1</translation>
    </message>
    <message>
        <source>the events stop after %1: %2</source>
        <translation>події обриваються після %1: %2</translation>
    </message>
    <message>
        <source>the events cannot be read: %1</source>
        <translation>не вдається прочитати події: %1</translation>
    </message>
    <message>
        <source>the routes stop early: %1</source>
        <translation>маршрути обриваються передчасно: %1</translation>
    </message>
    <message>
        <source>the routes cannot be read: %1</source>
        <translation>не вдається прочитати маршрути: %1</translation>
    </message>
    <message>
        <source>file:     %1
</source>
        <translation>файл:     %1
</translation>
    </message>
    <message>
        <source>span:     %1 to %2 (%3 s)
</source>
        <translation>період:   з %1 до %2 (%3 s)
</translation>
    </message>
    <message>
        <source>DAMAGED:  read up to the last good record; %1
</source>
        <translation>ПОШКОДЖЕНО: прочитано до останнього цілого запису; %1
</translation>
    </message>
    <message>
        <source>vehicles: %1
</source>
        <translation>апарати:  %1
</translation>
    </message>
    <message>
        <source>, %1 to %2</source>
        <translation>, з %1 до %2</translation>
    </message>
    <message>
        <source>    route uploaded %1: %2 waypoints
</source>
        <translation>    маршрут завантажено %1: точок: %2
</translation>
    </message>
    <message>
        <source>
events:   %1
</source>
        <translation>
події:    %1
</translation>
    </message>
    <message>
        <source> (failed)</source>
        <translation> (невдало)</translation>
    </message>
    <message>
        <source>a replayed vehicle takes no commands</source>
        <translation>апарат у відтворенні не приймає команд</translation>
    </message>
    <message>
        <source>block %1 (vehicle row %2, from %3) is skipped: %4</source>
        <translation>блок %1 (рядок апарата %2, від %3) пропущено: %4</translation>
    </message>
    <message numerus="yes">
        <source>%n more damaged block(s) skipped</source>
        <translation>
            <numerusform>ще %n пошкоджений блок пропущено</numerusform>
            <numerusform>ще %n пошкоджені блоки пропущено</numerusform>
            <numerusform>ще %n пошкоджених блоків пропущено</numerusform>
        </translation>
    </message>
    <message>
        <source>read up to the last good record: %1</source>
        <translation>прочитано до останнього справного запису: %1</translation>
    </message>
    <message>
        <source>DAMAGED:  %1
</source>
        <translation>ПОШКОДЖЕНО:  %1
</translation>
    </message>
    <message>
        <source>%1: cannot be opened: no private copy to recover it in (%2)</source>
        <translation>%1: не вдається відкрити: немає приватної копії для відновлення (%2)</translation>
    </message>
    <message>
        <source>%1 is not a Sortie flight log (its %2 is a %3, not a table)</source>
        <translation>%1 не є журналом польоту Sortie (його %2 є %3, а не таблицею)</translation>
    </message>
    <message>
        <source>stopped: %1</source>
        <translation>зупинено: %1</translation>
    </message>
</context>
<context>
    <name>QgcFenceJson</name>
    <message>
        <source>expected [latitude, longitude]</source>
        <translation>очікується [latitude, longitude]</translation>
    </message>
    <message>
        <source>latitude or longitude out of range</source>
        <translation>широта або довгота поза допустимими межами</translation>
    </message>
    <message>
        <source>expected [latitude, longitude, altitude]</source>
        <translation>очікується [latitude, longitude, altitude]</translation>
    </message>
    <message>
        <source>a polygon needs at least 3 vertices, found %1</source>
        <translation>полігону потрібно щонайменше 3 вершини, знайдено %1</translation>
    </message>
    <message>
        <source>Geofence polygon at %1 was left out: %2</source>
        <translation>Полігон геозони в %1 пропущено: %2</translation>
    </message>
    <message>
        <source>the radius must be positive metres</source>
        <translation>радіус має бути додатним числом метрів</translation>
    </message>
    <message>
        <source>The geofence&apos;s breach return point at %1 was left out: %2</source>
        <translation>Точку повернення геозони в разі порушення в %1 пропущено: %2</translation>
    </message>
    <message>
        <source>The geofence polygons at %1 were left out: %2</source>
        <translation>Полігони геозони в %1 пропущено: %2</translation>
    </message>
    <message>
        <source>Geofence circle at %1 was left out: %2</source>
        <translation>Коло геозони в %1 пропущено: %2</translation>
    </message>
    <message>
        <source>The geofence circles at %1 were left out: %2</source>
        <translation>Кола геозони в %1 пропущено: %2</translation>
    </message>
    <message>
        <source>Rally point at %1 was left out: %2</source>
        <translation>Точку збору в %1 пропущено: %2</translation>
    </message>
    <message>
        <source>The rally points at %1 were left out: %2</source>
        <translation>Точки збору в %1 пропущено: %2</translation>
    </message>
</context>
<context>
    <name>QgcPlanFormat</name>
    <message>
        <source>expected 7 params (or 4 and a &quot;coordinate&quot;), found %1</source>
        <translation>очікується 7 params (або 4 і &quot;coordinate&quot;), знайдено %1</translation>
    </message>
    <message>
        <source>not a QGroundControl plan (fileType is not &quot;Plan&quot;)</source>
        <translation>не план QGroundControl (fileType не &quot;Plan&quot;)</translation>
    </message>
    <message>
        <source>plan version %1 is not supported (Sortie reads version 1)</source>
        <translation>версія плану %1 не підтримується (Sortie читає версію 1)</translation>
    </message>
    <message>
        <source>mission version %1 is not supported (Sortie reads version 2)</source>
        <translation>версія місії %1 не підтримується (Sortie читає версію 2)</translation>
    </message>
    <message>
        <source>the planned home position is out of range</source>
        <translation>запланована точка дому поза допустимими межами</translation>
    </message>
    <message>
        <source>complex item &quot;%1&quot; is not supported; Sortie imports surveys, corridor and structure scans</source>
        <translation>складний елемент «%1» не підтримується; Sortie імпортує зйомки площі, сканування коридорів і споруд</translation>
    </message>
    <message>
        <source>unknown item type &quot;%1&quot;</source>
        <translation>невідомий тип елемента «%1»</translation>
    </message>
    <message>
        <source>A corridor was left out: %1</source>
        <translation>Коридор пропущено: %1</translation>
    </message>
    <message>
        <source>An area scan was left out: %1</source>
        <translation>Сканування площі пропущено: %1</translation>
    </message>
    <message>
        <source>The route has no home position: the first point was written as home, at 0 m AMSL.</source>
        <translation>Маршрут не має точки дому: першу точку записано як дім, на 0 m AMSL.</translation>
    </message>
</context>
<context>
    <name>QgcSurveyJson</name>
    <message>
        <source>latitude/longitude out of range</source>
        <translation>широта/довгота поза допустимими межами</translation>
    </message>
    <message>
        <source>a survey polygon needs at least 3 vertices, found %1</source>
        <translation>полігону зйомки потрібно щонайменше 3 вершини, знайдено %1</translation>
    </message>
    <message>
        <source>Custom Camera</source>
        <translation>Власна камера</translation>
    </message>
    <message>
        <source>the survey&apos;s camera has neither a sensor nor footprints</source>
        <translation>камера зйомки не має ні сенсора, ні розмірів кадру</translation>
    </message>
    <message>
        <source>%1: the survey&apos;s manual camera was replaced by one with the same footprints</source>
        <translation>%1: ручну камеру зйомки замінено на камеру з тими самими розмірами кадру</translation>
    </message>
    <message>
        <source>a %1 needs at least %2 points, found %3</source>
        <translation>%1: потрібно точок — щонайменше %2, знайдено %3</translation>
    </message>
    <message>
        <source>%1: the camera &quot;%2&quot; is not one Sortie knows; it is kept by name, and the server must know it.</source>
        <translation>%1: камера «%2» невідома Sortie; її збережено за назвою, і сервер має її знати.</translation>
    </message>
    <message>
        <source>the corridor&apos;s camera has no sensor to turn its distance into a ground sample distance</source>
        <translation>камера коридору не має сенсора, щоб перевести відстань у GSD</translation>
    </message>
    <message>
        <source>corridor centre line</source>
        <translation>осьова лінія коридору</translation>
    </message>
    <message>
        <source>structure polygon</source>
        <translation>полігон споруди</translation>
    </message>
    <message>
        <source>%1: the structure scan became a perimeter flight at %2 m%3.</source>
        <translation>%1: сканування споруди стало польотом по периметру на %2 m%3.</translation>
    </message>
    <message>
        <source>, its %1 layers as %1 loops at one height</source>
        <translation>, її шари (%1) стали витками на одній висоті</translation>
    </message>
</context>
<context>
    <name>RasterFootprint</name>
    <message>
        <source>the raster&apos;s geotransform cannot be inverted (a zero pixel size?)</source>
        <translation>геоперетворення растра не можна обернути (нульовий розмір пікселя?)</translation>
    </message>
    <message>
        <source>the raster has no pixels (%1×%2)</source>
        <translation>растр не має пікселів (%1×%2)</translation>
    </message>
    <message>
        <source>the raster&apos;s geotransform is not finite</source>
        <translation>геоперетворення растра не скінченне</translation>
    </message>
</context>
<context>
    <name>RemoveSegmentsCommand</name>
    <message>
        <source>Delete %1</source>
        <translation>Видалити %1</translation>
    </message>
    <message>
        <source>Delete %1 rows</source>
        <translation>Видалити рядки (%1)</translation>
    </message>
</context>
<context>
    <name>ReorderSegmentsCommand</name>
    <message>
        <source>Move row %1</source>
        <translation>Пересунути рядок %1</translation>
    </message>
    <message>
        <source>Move %1 rows</source>
        <translation>Пересунути рядки (%1)</translation>
    </message>
    <message>
        <source>Reverse rows %1-%2</source>
        <translation>Перевернути рядки %1-%2</translation>
    </message>
</context>
<context>
    <name>ReplayTimeline</name>
    <message>
        <source>Open a flight log</source>
        <translation>Відкрити журнал польоту</translation>
    </message>
    <message>
        <source>Flight logs (*.sortielog)</source>
        <translation>Журнали польотів (*.sortielog)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Усі файли (*)</translation>
    </message>
    <message>
        <source>Export tracks</source>
        <translation>Експорт треків</translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation>Експортовано в %1.</translation>
    </message>
    <message>
        <source>Open log…</source>
        <translation>Відкрити журнал…</translation>
    </message>
    <message>
        <source>Server history…</source>
        <translation>Історія сервера…</translation>
    </message>
    <message>
        <source>REPLAY — %1</source>
        <translation>ВІДТВОРЕННЯ — %1</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Відтворити</translation>
    </message>
    <message>
        <source>Previous event</source>
        <translation>Попередня подія</translation>
    </message>
    <message>
        <source>Next event</source>
        <translation>Наступна подія</translation>
    </message>
    <message>
        <source>Jump to event (%1)</source>
        <translation>Перейти до події (%1)</translation>
    </message>
    <message>
        <source>Loading plots…</source>
        <translation>Завантаження графіків…</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Експорт…</translation>
    </message>
    <message>
        <source>Back to live</source>
        <translation>До реального часу</translation>
    </message>
    <message>
        <source>Photos…</source>
        <translation>Знімки…</translation>
    </message>
</context>
<context>
    <name>RestoreDialog</name>
    <message>
        <source>Autosaved edits</source>
        <translation>Автозбережені зміни</translation>
    </message>
    <message>
        <source>Restore one of %1 unsaved routes?</source>
        <translation>Відновити один із незбережених маршрутів (%1)?</translation>
    </message>
    <message>
        <source>Restore unsaved edits?</source>
        <translation>Відновити незбережені зміни?</translation>
    </message>
    <message>
        <source>Sortie did not close normally. These routes had unsaved edits, saved automatically. Choose one to see its changes; the others are kept and offered again at the next start.</source>
        <translation>Sortie не завершився належним чином. Ці маршрути мали незбережені зміни, збережені автоматично. Виберіть один, щоб переглянути його зміни; решта зберігаються й будуть запропоновані знову під час наступного запуску.</translation>
    </message>
    <message>
        <source>Sortie did not close normally. Edits of “%1” were saved automatically at %2.</source>
        <translation>Sortie не завершився належним чином. Зміни «%1» збережено автоматично о %2.</translation>
    </message>
    <message>
        <source>%1 — saved %2</source>
        <translation>%1 — збережено %2</translation>
    </message>
    <message>
        <source>It belongs to %1.</source>
        <translation>Належить: %1.</translation>
    </message>
    <message>
        <source>Changes since the last save:</source>
        <translation>Зміни після останнього збереження:</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Відкинути</translation>
    </message>
    <message>
        <source>Start without these edits (the file is kept as a backup)</source>
        <translation>Почати без цих змін (файл зберігається як резервна копія)</translation>
    </message>
    <message>
        <source>Later</source>
        <translation>Пізніше</translation>
    </message>
    <message>
        <source>Keep them and decide after signing in</source>
        <translation>Зберегти їх і вирішити після входу</translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Відновити</translation>
    </message>
</context>
<context>
    <name>ResumePanel</name>
    <message>
        <source>Resume from the last photo</source>
        <translation>Продовжити з останнього фото</translation>
    </message>
    <message>
        <source>Resume from the last waypoint</source>
        <translation>Продовжити з останньої точки</translation>
    </message>
</context>
<context>
    <name>ResumeRoute</name>
    <message>
        <source>%1 cannot be resumed here: %2</source>
        <translation>%1 не можна продовжити тут: %2</translation>
    </message>
    <message>
        <source>the take-off point is not known</source>
        <translation>точка зльоту невідома</translation>
    </message>
    <message>
        <source>the route has nothing to fly</source>
        <translation>у маршруті немає чого летіти</translation>
    </message>
    <message>
        <source>none of the waypoints the vehicle reached is on this route&apos;s path: not this route&apos;s flight</source>
        <translation>жодна з досягнутих точок не лежить на шляху цього маршруту: це не політ цього маршруту</translation>
    </message>
    <message>
        <source>The last waypoint the vehicle reached is not one of the route&apos;s own: the rest starts at the route&apos;s point before it.</source>
        <translation>Остання досягнута точка не належить маршруту: решта починається з точки маршруту перед нею.</translation>
    </message>
    <message>
        <source>where the last photo was taken is not known</source>
        <translation>невідомо, де зроблено останнє фото</translation>
    </message>
    <message>
        <source>the last photo was taken %1 m from the route&apos;s path, more than the %2 m a flight of it strays: not this route&apos;s flight</source>
        <translation>останнє фото зроблено за %1 м від шляху маршруту, більше ніж %2 м відхилення польоту: це не політ цього маршруту</translation>
    </message>
    <message>
        <source>The photos were taken every %1 s: the next one is taken as due %2 m on at the leg&apos;s speed.</source>
        <translation>Фото робилися кожні %1 с: наступне вважається належним через %2 м на швидкості відрізка.</translation>
    </message>
    <message>
        <source>No photo series was running at the last photo: the rest starts where it was taken.</source>
        <translation>На останньому фото серія не йшла: решта починається там, де його зроблено.</translation>
    </message>
    <message>
        <source>the last photo was the route&apos;s last: nothing is left to fly</source>
        <translation>останнє фото було останнім у маршруті: летіти більше нічого</translation>
    </message>
    <message>
        <source>the route was flown to its last point: nothing is left to fly</source>
        <translation>маршрут пройдено до останньої точки: летіти більше нічого</translation>
    </message>
    <message>
        <source>%1 (resumed)</source>
        <translation>%1 (продовження)</translation>
    </message>
    <message>
        <source>Route</source>
        <translation>Маршрут</translation>
    </message>
    <message>
        <source>Resumes %1, %2 m into the flight (%3 m left), after a take-off and a flight over at %4 m.</source>
        <translation>Продовжує %1 через %2 м від початку польоту (лишилося %3 м), після зльоту й перельоту на %4 м.</translation>
    </message>
    <message>
        <source>The photo series every %1 m starts again at the resume point.</source>
        <translation>Серія фото кожні %1 м починається знову в точці продовження.</translation>
    </message>
    <message>
        <source>The photo series every %1 s starts again at the resume point.</source>
        <translation>Серія фото кожні %1 с починається знову в точці продовження.</translation>
    </message>
    <message>
        <source>The gimbal is tilted to %1° there, as it was.</source>
        <translation>Підвіс там нахилено на %1°, як було.</translation>
    </message>
    <message>
        <source>the place to resume from is not on the route&apos;s path</source>
        <translation>місце продовження не лежить на шляху маршруту</translation>
    </message>
    <message>
        <source>the place to resume from is %1 m from where the route&apos;s path is that far along</source>
        <translation>місце продовження за %1 м від точки, де шлях маршруту сягає такої відстані</translation>
    </message>
</context>
<context>
    <name>RouteDiff</name>
    <message>
        <source>WP %1</source>
        <translation>ТМ %1</translation>
    </message>
    <message>
        <source>Scan %1</source>
        <translation>Сканування %1</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(немає)</translation>
    </message>
    <message>
        <source>return home</source>
        <translation>повернення додому</translation>
    </message>
    <message>
        <source>none</source>
        <translation>немає</translation>
    </message>
    <message>
        <source>No changes</source>
        <translation>Без змін</translation>
    </message>
    <message>
        <source>1 change: </source>
        <translation>1 зміна: </translation>
    </message>
    <message>
        <source>%1 changes: </source>
        <translation>Змін: %1: </translation>
    </message>
    <message>
        <source> and %1 more</source>
        <translation> і ще %1</translation>
    </message>
    <message>
        <source>name %1 → %2</source>
        <translation>назва %1 → %2</translation>
    </message>
    <message>
        <source>%1 %2 → %3 %4</source>
        <translation>%1 %2 → %3 %4</translation>
    </message>
    <message>
        <source>safe altitude</source>
        <translation>безпечна висота</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>maximum altitude</source>
        <translation>максимальна висота</translation>
    </message>
    <message>
        <source>initial speed</source>
        <translation>початкова швидкість</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>maximum speed</source>
        <translation>максимальна швидкість</translation>
    </message>
    <message>
        <source>corner radius</source>
        <translation>радіус повороту</translation>
    </message>
    <message>
        <source>takeoff height</source>
        <translation>висота зльоту</translation>
    </message>
    <message>
        <source>vehicle profile %1 → %2</source>
        <translation>профіль апарата %1 → %2</translation>
    </message>
    <message>
        <source>vehicle profile %1 changed</source>
        <translation>профіль апарата %1 змінено</translation>
    </message>
    <message>
        <source>failsafe actions changed</source>
        <translation>аварійні дії змінено</translation>
    </message>
    <message>
        <source>home set</source>
        <translation>точку дому задано</translation>
    </message>
    <message>
        <source>home removed</source>
        <translation>точку дому видалено</translation>
    </message>
    <message>
        <source>home moved %1 m</source>
        <translation>точку дому зміщено на %1 m</translation>
    </message>
    <message>
        <source>home altitude %1 → %2 m</source>
        <translation>висота точки дому %1 → %2 m</translation>
    </message>
    <message>
        <source>end action %1 → %2</source>
        <translation>дія в кінці %1 → %2</translation>
    </message>
    <message>
        <source>on</source>
        <translation>увімк.</translation>
    </message>
    <message>
        <source>off</source>
        <translation>вимк.</translation>
    </message>
    <message>
        <source>aerodrome zone check</source>
        <translation>перевірка зон аеродромів</translation>
    </message>
    <message>
        <source>custom zone check</source>
        <translation>перевірка власних зон</translation>
    </message>
    <message>
        <source>%1 removed</source>
        <translation>%1 видалено</translation>
    </message>
    <message>
        <source>%1 added</source>
        <translation>%1 додано</translation>
    </message>
    <message>
        <source>%1 changed</source>
        <translation>%1 змінено</translation>
    </message>
    <message>
        <source>%1 moved %2 m</source>
        <translation>%1 зміщено на %2 m</translation>
    </message>
    <message>
        <source>altitude of %1 %2 m %3 → %4 m %5</source>
        <translation>висота %1: %2 m %3 → %4 m %5</translation>
    </message>
    <message>
        <source>altitude of %1 %2 → %3 m</source>
        <translation>висота %1: %2 → %3 m</translation>
    </message>
    <message>
        <source>speed of %1 %2 → %3 m/s</source>
        <translation>швидкість %1: %2 → %3 m/s</translation>
    </message>
    <message>
        <source>actions of %1: %2 → %3</source>
        <translation>дії %1: %2 → %3</translation>
    </message>
    <message>
        <source>turn at %1 %2 → %3</source>
        <translation>поворот у %1: %2 → %3</translation>
    </message>
    <message>
        <source>acceptance radius of %1 %2 → %3 m</source>
        <translation>радіус досягнення %1: %2 → %3 m</translation>
    </message>
    <message>
        <source>%1 %2 → %3</source>
        <translation>%1: %2 → %3</translation>
    </message>
    <message>
        <source>figure of %1 reshaped</source>
        <translation>фігуру %1 змінено</translation>
    </message>
    <message>
        <source>%1 of %2 %3 → %4</source>
        <translation>%1 для %2: %3 → %4</translation>
    </message>
    <message>
        <source>%1 of %2 removed</source>
        <translation>%1 для %2 видалено</translation>
    </message>
    <message>
        <source>actions of %1 changed</source>
        <translation>дії %1 змінено</translation>
    </message>
    <message>
        <source>area of %1 reshaped</source>
        <translation>район %1 змінено</translation>
    </message>
    <message>
        <source>area of %1 reshaped (%2 → %3 corners)</source>
        <translation>район %1 змінено (кутів: %2 → %3)</translation>
    </message>
    <message>
        <source>%1 of %2 %3 → %4 %5</source>
        <translation>%1 для %2: %3 → %4 %5</translation>
    </message>
    <message>
        <source>altitude</source>
        <translation>висота</translation>
    </message>
    <message>
        <source>altitude of %1 now %2</source>
        <translation>висота %1 тепер %2</translation>
    </message>
    <message>
        <source>%1 now flies by ground sample distance</source>
        <translation>%1 тепер летить за GSD (розмір пікселя на місцевості)</translation>
    </message>
    <message>
        <source>%1 now flies by altitude</source>
        <translation>%1 тепер летить за висотою</translation>
    </message>
    <message>
        <source>front overlap</source>
        <translation>поздовжнє перекриття</translation>
    </message>
    <message>
        <source>side overlap</source>
        <translation>бічне перекриття</translation>
    </message>
    <message>
        <source>direction</source>
        <translation>напрямок</translation>
    </message>
    <message>
        <source>turnaround</source>
        <translation>розворот</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>швидкість</translation>
    </message>
    <message>
        <source>camera of %1 %2 → %3</source>
        <translation>камера %1: %2 → %3</translation>
    </message>
    <message>
        <source>camera of %1 changed</source>
        <translation>камеру %1 змінено</translation>
    </message>
    <message>
        <source>planned start %1</source>
        <translation>запланований старт %1</translation>
    </message>
    <message>
        <source>planned start removed: now</source>
        <translation>запланований старт прибрано: зараз</translation>
    </message>
    <message>
        <source>authorisation for %1: %2</source>
        <translation>дозвіл для %1: %2</translation>
    </message>
    <message>
        <source>authorisation for %1 removed</source>
        <translation>дозвіл для %1 прибрано</translation>
    </message>
</context>
<context>
    <name>RouteEndurance</name>
    <message>
        <source>No energy profile: choose the vehicle&apos;s profile file</source>
        <translation>Немає енергетичного профілю: виберіть файл профілю апарата</translation>
    </message>
    <message>
        <source>The route has no points</source>
        <translation>Маршрут не має точок</translation>
    </message>
</context>
<context>
    <name>RoutePanel</name>
    <message>
        <source>Import a route</source>
        <translation>Імпорт маршруту</translation>
    </message>
    <message>
        <source>Routes (*.sortie *.plan *.waypoints *.txt *.kml *.kmz)</source>
        <translation>Маршрути (*.sortie *.plan *.waypoints *.txt *.kml *.kmz)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Усі файли (*)</translation>
    </message>
    <message>
        <source>The vehicle&apos;s energy profile</source>
        <translation>Енергетичний профіль апарата</translation>
    </message>
    <message>
        <source>Energy profiles (*.json)</source>
        <translation>Енергетичні профілі (*.json)</translation>
    </message>
    <message>
        <source>Export the route</source>
        <translation>Експорт маршруту</translation>
    </message>
    <message>
        <source>Sortie (*.sortie)</source>
        <translation>Sortie (*.sortie)</translation>
    </message>
    <message>
        <source>QGroundControl plan (*.plan)</source>
        <translation>План QGroundControl (*.plan)</translation>
    </message>
    <message>
        <source>Waypoint list (*.waypoints)</source>
        <translation>Список точок (*.waypoints)</translation>
    </message>
    <message>
        <source>KML (*.kml)</source>
        <translation>KML (*.kml)</translation>
    </message>
    <message>
        <source>DJI Pilot 2 route, WPML (*.kmz)</source>
        <translation>Маршрут DJI Pilot 2, WPML (*.kmz)</translation>
    </message>
    <message>
        <source>Choose a route…</source>
        <translation>Виберіть маршрут…</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Відкрити</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Зберегти</translation>
    </message>
    <message>
        <source>Save on the server, under its lock (Ctrl+S)</source>
        <translation>Зберегти на сервері під його блокуванням (Ctrl+S)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Вернути</translation>
    </message>
    <message>
        <source>Undo %1 (Ctrl+Z)</source>
        <translation>Вернути: %1 (Ctrl+Z)</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Повторити</translation>
    </message>
    <message>
        <source>Redo %1 (Ctrl+Shift+Z)</source>
        <translation>Повторити: %1 (Ctrl+Shift+Z)</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Видалити</translation>
    </message>
    <message>
        <source>Delete the selected waypoints (Del)</source>
        <translation>Видалити вибрані точки (Del)</translation>
    </message>
    <message>
        <source>Area scan</source>
        <translation>Сканування площі</translation>
    </message>
    <message>
        <source>Draw an area to scan: click its corners on the map</source>
        <translation>Намалюйте район для сканування: клацніть його кути на карті</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>Імпорт…</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Експорт…</translation>
    </message>
    <message>
        <source>Zone checks…</source>
        <translation>Перевірка зон…</translation>
    </message>
    <message>
        <source>Which no-fly zones the server&apos;s processing refuses the route for</source>
        <translation>Через які заборонені зони обробка на сервері відхиляє маршрут</translation>
    </message>
    <message>
        <source>Refuse crossing aerodrome zones</source>
        <translation>Відхиляти перетин зон аеродромів</translation>
    </message>
    <message>
        <source>Refuse crossing custom zones</source>
        <translation>Відхиляти перетин власних зон</translation>
    </message>
    <message>
        <source>Process</source>
        <translation>Обробити</translation>
    </message>
    <message>
        <source>Prepare the route for the chosen vehicle, as the upload will, and show what it would fly (Ctrl+P)</source>
        <translation>Підготувати маршрут для вибраного апарата, як це зробить завантаження, і показати, що він пролетить (Ctrl+P)</translation>
    </message>
    <message>
        <source>Vehicle…</source>
        <translation>Апарат…</translation>
    </message>
    <message>
        <source>Upload</source>
        <translation>Завантажити</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Скасувати</translation>
    </message>
    <message>
        <source>Yours (version %1, edited) against theirs (version %2, grey on the map):</source>
        <translation>Ваша (версія %1, змінена) проти їхньої (версія %2, сіра на карті):</translation>
    </message>
    <message>
        <source>They changed: %1</source>
        <translation>Вони змінили: %1</translation>
    </message>
    <message>
        <source>Keep mine (overwrite theirs)</source>
        <translation>Залишити мою (перезаписати їхню)</translation>
    </message>
    <message>
        <source>Take theirs (undo brings mine back)</source>
        <translation>Взяти їхню («Вернути» поверне мою)</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Довжина</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Час</translation>
    </message>
    <message>
        <source>Waypoints</source>
        <translation>Точки</translation>
    </message>
    <message>
        <source>Photos</source>
        <translation>Фото</translation>
    </message>
    <message>
        <source>Conflicts with other vehicles</source>
        <translation>Конфлікти з іншими апаратами</translation>
    </message>
    <message>
        <source>%1:%2  leg %3 · %4 (%5): %6 m across, %7 m in height</source>
        <translation>%1:%2  ділянка %3 · %4 (%5): %6 m по горизонталі, %7 m по висоті</translation>
    </message>
    <message>
        <source>flying</source>
        <translation>у польоті</translation>
    </message>
    <message>
        <source>uploaded</source>
        <translation>завантажено</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Енергія</translation>
    </message>
    <message>
        <source>%1 Wh</source>
        <translation>%1 Wh</translation>
    </message>
    <message numerus="yes">
        <source>%n batteries</source>
        <translation>
            <numerusform>%n батарея</numerusform>
            <numerusform>%n батареї</numerusform>
            <numerusform>%n батарей</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 % left</source>
        <translation>лишиться %1 %</translation>
    </message>
    <message>
        <source>No return</source>
        <translation>Точка неповернення</translation>
    </message>
    <message>
        <source>unknown: no home</source>
        <translation>невідомо: немає дому</translation>
    </message>
    <message>
        <source>after %1 (leg %2)</source>
        <translation>після %1 (ділянка %2)</translation>
    </message>
    <message>
        <source>none: home in reach</source>
        <translation>немає: дім у межах досяжності</translation>
    </message>
    <message>
        <source>Beyond this point of the route, flying straight home no longer lands with the reserve</source>
        <translation>Після цієї точки маршруту прямий політ додому вже не завершиться посадкою з резервом</translation>
    </message>
    <message>
        <source>Load an energy profile to see whether the battery lasts.</source>
        <translation>Виберіть енергетичний профіль, щоб побачити, чи вистачить батареї.</translation>
    </message>
    <message>
        <source>Profile</source>
        <translation>Профіль</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>unnamed</source>
        <translation>без назви</translation>
    </message>
    <message>
        <source>none</source>
        <translation>немає</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Вибрати…</translation>
    </message>
    <message>
        <source>The vehicle&apos;s energy profile: a JSON file, e.g. from sortie-log fit</source>
        <translation>Енергетичний профіль апарата: файл JSON, напр. від sortie-log fit</translation>
    </message>
    <message>
        <source>Wind</source>
        <translation>Вітер</translation>
    </message>
    <message>
        <source>Wind speed, m/s</source>
        <translation>Швидкість вітру, m/s</translation>
    </message>
    <message>
        <source>m/s from</source>
        <translation>m/s, з</translation>
    </message>
    <message>
        <source>The direction the wind blows from, degrees clockwise from north</source>
        <translation>Напрямок, звідки дме вітер, у градусах за годинниковою стрілкою від півночі</translation>
    </message>
    <message>
        <source>Select the segment</source>
        <translation>Вибрати сегмент</translation>
    </message>
    <message>
        <source>Planned start</source>
        <translation>Запланований старт</translation>
    </message>
    <message>
        <source>now (or e.g. %1)</source>
        <translation>зараз (або напр. %1)</translation>
    </message>
    <message>
        <source>Year-month-day hours:minutes, your time zone; empty: the flight starts now</source>
        <translation>Рік-місяць-день години:хвилини, ваш часовий пояс; порожньо: політ починається зараз</translation>
    </message>
</context>
<context>
    <name>RouteValidator</name>
    <message>
        <source>%1: the position is not valid.</source>
        <translation>%1: позиція некоректна.</translation>
    </message>
    <message>
        <source>The route needs at least two points; it has %1.</source>
        <translation>Маршрутові потрібно щонайменше дві точки; він має %1.</translation>
    </message>
    <message numerus="yes">
        <source>%n AMSL altitude(s), the first at %1, were not checked against the route&apos;s limits: the take-off elevation is unknown.</source>
        <translation>
            <numerusform>%n висоту AMSL (перша — %1) не перевірено щодо обмежень маршруту: висота місця зльоту невідома.</numerusform>
            <numerusform>%n висоти AMSL (перша — %1) не перевірено щодо обмежень маршруту: висота місця зльоту невідома.</numerusform>
            <numerusform>%n висот AMSL (перша — %1) не перевірено щодо обмежень маршруту: висота місця зльоту невідома.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: altitude %2 is below the route&apos;s safe altitude of %3 m.</source>
        <translation>%1: висота %2 нижча за безпечну висоту маршруту %3 m.</translation>
    </message>
    <message>
        <source>%1: the speed must be positive.</source>
        <translation>%1: швидкість має бути додатною.</translation>
    </message>
    <message>
        <source>%1: speed %2 m/s is above the vehicle&apos;s limit of %3 m/s.</source>
        <translation>%1: швидкість %2 m/s перевищує обмеження апарата %3 m/s.</translation>
    </message>
    <message>
        <source>%1: Sortie does not know the algorithm %2; the server checks it when it processes the route.</source>
        <translation>%1: Sortie не знає алгоритму %2; сервер перевірить його під час обробки маршруту.</translation>
    </message>
    <message>
        <source>%1 repeats %2.</source>
        <translation>%1 повторює %2.</translation>
    </message>
    <message>
        <source>%1 is %2 but %3 is %4: the climb between them is not estimated.</source>
        <translation>%1 — %2, але %3 — %4: набір висоти між ними не оцінюється.</translation>
    </message>
    <message>
        <source>The route</source>
        <translation>Маршрут</translation>
    </message>
    <message>
        <source>%1: %2 m above the take-off point (altitude %3); the route&apos;s limit is %4 m above it.</source>
        <translation>%1: %2 m над точкою зльоту (висота %3); межа маршруту — %4 m над нею.</translation>
    </message>
</context>
<context>
    <name>SbsFeed</name>
    <message>
        <source>line %1: %2</source>
        <translation>рядок %1: %2</translation>
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
        <translation>3D-вигляду потрібен OpenGL: запустіть Sortie з QSG_RHI_BACKEND=opengl.</translation>
    </message>
    <message>
        <source>Open a route to see it in 3D.</source>
        <translation>Відкрийте маршрут, щоб побачити його в 3D.</translation>
    </message>
    <message>
        <source>Purple ground: no elevation data there.</source>
        <translation>Фіолетова земля: там немає даних висот.</translation>
    </message>
    <message>
        <source>Vertical exaggeration</source>
        <translation>Вертикальне перебільшення</translation>
    </message>
    <message>
        <source>Fit route</source>
        <translation>Показати маршрут</translation>
    </message>
</context>
<context>
    <name>SegmentEditor</name>
    <message>
        <source>Radius</source>
        <translation>Радіус</translation>
    </message>
    <message>
        <source>Advanced parameters</source>
        <translation>Додаткові параметри</translation>
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
        <translation>Радіус досягнення</translation>
    </message>
    <message>
        <source>Sensor width (mm)</source>
        <translation>Ширина сенсора (mm)</translation>
    </message>
    <message>
        <source>Sensor height (mm)</source>
        <translation>Висота сенсора (mm)</translation>
    </message>
    <message>
        <source>Focal length (mm)</source>
        <translation>Фокусна відстань (mm)</translation>
    </message>
    <message>
        <source>Image width (px)</source>
        <translation>Ширина зображення (px)</translation>
    </message>
    <message>
        <source>Image height (px)</source>
        <translation>Висота зображення (px)</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Висота</translation>
    </message>
    <message>
        <source>Side distance (0: from the camera)</source>
        <translation>Бічна відстань (0: за камерою)</translation>
    </message>
</context>
<context>
    <name>SegmentParameters</name>
    <message>
        <source>%1 needs a number, not &quot;%2&quot;.</source>
        <translation>Для %1 потрібне число, а не «%2».</translation>
    </message>
    <message>
        <source>altitudeType is AGL or AMSL, not &quot;%1&quot;.</source>
        <translation>altitudeType — це AGL або AMSL, а не «%1».</translation>
    </message>
    <message>
        <source>camera needs a name.</source>
        <translation>camera: потрібна назва.</translation>
    </message>
    <message>
        <source>An area scan has no parameter &quot;%1&quot;.</source>
        <translation>Сканування площі не має параметра «%1».</translation>
    </message>
    <message>
        <source>wpTurnType is STOP_AND_TURN, STRAIGHT, SPLINE or BANK_TURN, not &quot;%1&quot;.</source>
        <translation>wpTurnType — це STOP_AND_TURN, STRAIGHT, SPLINE або BANK_TURN, а не «%1».</translation>
    </message>
    <message>
        <source>A waypoint has no parameter &quot;%1&quot;.</source>
        <translation>Точка маршруту не має параметра «%1».</translation>
    </message>
    <message>
        <source>%1 has no parameter &quot;%2&quot;.</source>
        <translation>%1 не має параметра «%2».</translation>
    </message>
    <message>
        <source>%1 cannot take that value.</source>
        <translation>%1 не може мати такого значення.</translation>
    </message>
    <message>
        <source>%1 is true or false, not &quot;%2&quot;.</source>
        <translation>%1 — це true або false, а не «%2».</translation>
    </message>
    <message>
        <source>%1 must be from %2 to below %3.</source>
        <translation>%1 має бути від %2 до менше ніж %3.</translation>
    </message>
    <message>
        <source>%1 must be from %2 to %3.</source>
        <translation>%1 має бути від %2 до %3.</translation>
    </message>
</context>
<context>
    <name>SegmentPlanner</name>
    <message>
        <source>The segment has no point</source>
        <translation>Сегмент не має точки</translation>
    </message>
    <message>
        <source>Point 1 is not a position on the globe</source>
        <translation>Точка 1 не є позицією на земній кулі</translation>
    </message>
    <message>
        <source>The circle has no centre point</source>
        <translation>Коло не має центральної точки</translation>
    </message>
    <message>
        <source>The circle&apos;s centre is not a position on the globe</source>
        <translation>Центр кола не є позицією на земній кулі</translation>
    </message>
    <message>
        <source>The circle needs a positive radius (metres, the figure&apos;s first parameter)</source>
        <translation>Колу потрібен додатний радіус (у метрах, перший параметр фігури)</translation>
    </message>
    <message>
        <source>The circle&apos;s radius of %1 m is over the %2 m a segment may span</source>
        <translation>Радіус кола %1 m перевищує %2 m, які може охоплювати сегмент</translation>
    </message>
    <message>
        <source>loops: %1 laps of %2 points are too many</source>
        <translation>loops: %1 кіл по %2 точок — забагато</translation>
    </message>
    <message numerus="yes">
        <source>Orbit of %1 m radius: %n lap(s) of %2 points, %3</source>
        <translation>
            <numerusform>Орбіта радіусом %1 m: %n коло (точок на коло: %2), %3</numerusform>
            <numerusform>Орбіта радіусом %1 m: %n кола (точок на коло: %2), %3</numerusform>
            <numerusform>Орбіта радіусом %1 m: %n кіл (точок на коло: %2), %3</numerusform>
        </translation>
    </message>
    <message>
        <source>clockwise</source>
        <translation>за годинниковою стрілкою</translation>
    </message>
    <message>
        <source>counter-clockwise</source>
        <translation>проти годинникової стрілки</translation>
    </message>
    <message>
        <source>Point %1 is not a position on the globe (latitude and longitude in range)</source>
        <translation>Точка %1 не є позицією на земній кулі (широта й довгота в допустимих межах)</translation>
    </message>
    <message>
        <source>speed: the segment needs a positive speed</source>
        <translation>speed: сегментові потрібна додатна швидкість</translation>
    </message>
    <message>
        <source>No planner knows the algorithm &apos;%1&apos;</source>
        <translation>Жоден планувальник не знає алгоритму «%1»</translation>
    </message>
</context>
<context>
    <name>SegmentWaypoints</name>
    <message>
        <source>cannot be planned</source>
        <translation>не вдається спланувати</translation>
    </message>
    <message>
        <source>only a UgCS server that knows %1 can plan it</source>
        <translation>спланувати це може лише сервер UgCS, що знає %1</translation>
    </message>
    <message>
        <source>no such segment</source>
        <translation>такого сегмента немає</translation>
    </message>
</context>
<context>
    <name>ServerAction</name>
    <message>
        <source>Server action</source>
        <translation>Серверна дія</translation>
    </message>
</context>
<context>
    <name>ServerAddress</name>
    <message>
        <source>the server address is empty (expected host:port)</source>
        <translation>адреса сервера порожня (очікується host:port)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; opens an IPv6 address with [ but never closes it</source>
        <translation>«%1» відкриває адресу IPv6 дужкою [, але не закриває її</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has text after the IPv6 address that is not :port</source>
        <translation>«%1» має після адреси IPv6 текст, який не є :port</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an IPv6 address</source>
        <translation>«%1» не є адресою IPv6</translation>
    </message>
    <message>
        <source>write an IPv6 server address in brackets: [%1]:3334</source>
        <translation>запишіть адресу сервера IPv6 у дужках: [%1]:3334</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no host name</source>
        <translation>«%1» не має імені хоста</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a host name (expected host:port, e.g. localhost:3334)</source>
        <translation>«%1» не є іменем хоста (очікується host:port, напр. localhost:3334)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a port number (1 to 65535)</source>
        <translation>«%1» не є номером порту (від 1 до 65535)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is a URL: give the server as host:port, e.g. localhost:3334 (or tls://host:port over TLS)</source>
        <translation>«%1» — це URL: вкажіть сервер як вузол:порт, напр. localhost:3334 (або tls://вузол:порт через TLS)</translation>
    </message>
</context>
<context>
    <name>ServerHistoryDialog</name>
    <message>
        <source>Server history</source>
        <translation>Історія сервера</translation>
    </message>
    <message>
        <source>Vehicle</source>
        <translation>Апарат</translation>
    </message>
    <message>
        <source>From (UTC)</source>
        <translation>Від (UTC)</translation>
    </message>
    <message>
        <source>To (UTC)</source>
        <translation>До (UTC)</translation>
    </message>
    <message>
        <source>Last hour</source>
        <translation>Остання година</translation>
    </message>
    <message>
        <source>Fetch and replay</source>
        <translation>Отримати й відтворити</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Скасувати</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Закрити</translation>
    </message>
</context>
<context>
    <name>ServerZoneReply</name>
    <message>
        <source>the server gave no reason</source>
        <translation>сервер не вказав причини</translation>
    </message>
</context>
<context>
    <name>SetNfzChecksCommand</name>
    <message>
        <source>Check aerodrome zones</source>
        <translation>Перевіряти зони аеродромів</translation>
    </message>
    <message>
        <source>Do not check aerodrome zones</source>
        <translation>Не перевіряти зони аеродромів</translation>
    </message>
    <message>
        <source>Check custom zones</source>
        <translation>Перевіряти власні зони</translation>
    </message>
    <message>
        <source>Do not check custom zones</source>
        <translation>Не перевіряти власні зони</translation>
    </message>
</context>
<context>
    <name>ShortcutHelp</name>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Гарячі клавіші</translation>
    </message>
    <message>
        <source>On the map</source>
        <translation>На карті</translation>
    </message>
    <message>
        <source>Esc closes this help.</source>
        <translation>Esc закриває цю довідку.</translation>
    </message>
</context>
<context>
    <name>Shortcuts</name>
    <message>
        <source>Pan the map (Shift: faster)</source>
        <translation>Пересунути карту (Shift: швидше)</translation>
    </message>
    <message>
        <source>Zoom in / out (also the mouse wheel and pinch)</source>
        <translation>Наблизити / віддалити (також коліщатко миші й жест щипка)</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Перетягування</translation>
    </message>
    <message>
        <source>Pan the map</source>
        <translation>Пересунути карту</translation>
    </message>
    <message>
        <source>Shift+Drag</source>
        <translation>Shift+перетягування</translation>
    </message>
    <message>
        <source>Select waypoints in a rectangle (Ctrl+Shift adds)</source>
        <translation>Вибрати точки прямокутником (Ctrl+Shift додає)</translation>
    </message>
    <message>
        <source>Click</source>
        <translation>Клацання</translation>
    </message>
    <message>
        <source>Add a waypoint; on a leg: insert one; on a waypoint: select (Ctrl toggles, Shift extends)</source>
        <translation>Додати точку; на ділянці: вставити; на точці: вибрати (Ctrl перемикає, Shift розширює)</translation>
    </message>
    <message>
        <source>Drag a waypoint</source>
        <translation>Перетягування точки</translation>
    </message>
    <message>
        <source>Move it, or the whole selection</source>
        <translation>Пересунути її або весь вибір</translation>
    </message>
    <message>
        <source>Show or hide this help</source>
        <translation>Показати або сховати цю довідку</translation>
    </message>
    <message>
        <source>Login page</source>
        <translation>Сторінка входу</translation>
    </message>
    <message>
        <source>Mission page</source>
        <translation>Сторінка місії</translation>
    </message>
    <message>
        <source>Live telemetry page</source>
        <translation>Сторінка телеметрії</translation>
    </message>
    <message>
        <source>Save the route on the server</source>
        <translation>Зберегти маршрут на сервері</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Вернути</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Повторити</translation>
    </message>
    <message>
        <source>Delete the selected waypoints</source>
        <translation>Видалити вибрані точки</translation>
    </message>
    <message>
        <source>Process the route on the server</source>
        <translation>Обробити маршрут на сервері</translation>
    </message>
    <message>
        <source>Choose the map source</source>
        <translation>Вибрати джерело карти</translation>
    </message>
    <message>
        <source>Focus the map (then arrows and +/− move it)</source>
        <translation>Фокус на карту (потім стрілки й +/− рухають її)</translation>
    </message>
    <message>
        <source>Full screen on or off</source>
        <translation>Повноекранний режим увімк./вимк.</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Вийти</translation>
    </message>
</context>
<context>
    <name>SortieFormat</name>
    <message>
        <source>not a valid UgCS %1</source>
        <translation>некоректний %1 UgCS</translation>
    </message>
    <message>
        <source>missing &quot;AGL&quot; or &quot;AMSL&quot;</source>
        <translation>бракує &quot;AGL&quot; або &quot;AMSL&quot;</translation>
    </message>
    <message>
        <source>expected &quot;AGL&quot; or &quot;AMSL&quot;</source>
        <translation>очікується &quot;AGL&quot; або &quot;AMSL&quot;</translation>
    </message>
    <message>
        <source>unknown value &quot;%1&quot;</source>
        <translation>невідоме значення «%1»</translation>
    </message>
    <message>
        <source>latitude out of range</source>
        <translation>широта поза допустимими межами</translation>
    </message>
    <message>
        <source>longitude out of range</source>
        <translation>довгота поза допустимими межами</translation>
    </message>
    <message>
        <source>latitude/longitude out of range</source>
        <translation>широта/довгота поза допустимими межами</translation>
    </message>
    <message>
        <source>expected &quot;altitude&quot; or &quot;groundSampleDistance&quot;</source>
        <translation>очікується &quot;altitude&quot; або &quot;groundSampleDistance&quot;</translation>
    </message>
    <message>
        <source>no figure type %1</source>
        <translation>немає типу фігури %1</translation>
    </message>
    <message>
        <source>unknown segment type &quot;%1&quot;</source>
        <translation>невідомий тип сегмента «%1»</translation>
    </message>
    <message>
        <source>expected &quot;none&quot; or &quot;returnHome&quot;</source>
        <translation>очікується &quot;none&quot; або &quot;returnHome&quot;</translation>
    </message>
    <message>
        <source>not a Sortie mission file (&quot;format&quot; is not &quot;sortie-mission&quot;)</source>
        <translation>не файл місії Sortie (&quot;format&quot; не &quot;sortie-mission&quot;)</translation>
    </message>
    <message>
        <source>schema version %1 does not exist</source>
        <translation>версії схеми %1 не існує</translation>
    </message>
    <message>
        <source>written by a newer Sortie (schema %1); this one reads up to schema %2</source>
        <translation>записано новішою версією Sortie (схема %1); ця читає схеми до %2</translation>
    </message>
    <message>
        <source>expected a date and time in UTC, e.g. 2026-06-06T18:00:00Z</source>
        <translation>очікувалися дата й час в UTC, напр. 2026-06-06T18:00:00Z</translation>
    </message>
    <message>
        <source>an authorisation needs the zone&apos;s identifier</source>
        <translation>дозвіл потребує ідентифікатора зони</translation>
    </message>
</context>
<context>
    <name>StatusBar</name>
    <message>
        <source>zoom %1</source>
        <translation>масштаб %1</translation>
    </message>
</context>
<context>
    <name>TelemetryFieldNames</name>
    <message>
        <source>Latitude</source>
        <translation>Широта</translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation>Довгота</translation>
    </message>
    <message>
        <source>Altitude (AMSL)</source>
        <translation>Висота (над рівнем моря)</translation>
    </message>
    <message>
        <source>Altitude above home</source>
        <translation>Висота над точкою старту</translation>
    </message>
    <message>
        <source>Roll</source>
        <translation>Крен</translation>
    </message>
    <message>
        <source>Pitch</source>
        <translation>Тангаж</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Курс</translation>
    </message>
    <message>
        <source>Course</source>
        <translation>Шляховий кут</translation>
    </message>
    <message>
        <source>Ground speed</source>
        <translation>Шляхова швидкість</translation>
    </message>
    <message>
        <source>Air speed</source>
        <translation>Повітряна швидкість</translation>
    </message>
    <message>
        <source>Vertical speed</source>
        <translation>Вертикальна швидкість</translation>
    </message>
    <message>
        <source>Battery voltage</source>
        <translation>Напруга батареї</translation>
    </message>
    <message>
        <source>Battery current</source>
        <translation>Струм батареї</translation>
    </message>
    <message>
        <source>Battery remaining</source>
        <translation>Залишок заряду</translation>
    </message>
    <message>
        <source>GPS fix</source>
        <translation>GPS-фіксація</translation>
    </message>
    <message>
        <source>Satellites</source>
        <translation>Супутники</translation>
    </message>
    <message>
        <source>HDOP</source>
        <translation>HDOP</translation>
    </message>
    <message>
        <source>Home latitude</source>
        <translation>Широта точки старту</translation>
    </message>
    <message>
        <source>Home longitude</source>
        <translation>Довгота точки старту</translation>
    </message>
    <message>
        <source>Home altitude (AMSL)</source>
        <translation>Висота точки старту (над рівнем моря)</translation>
    </message>
    <message>
        <source>Armed</source>
        <translation>Озброєно</translation>
    </message>
    <message>
        <source>Flight mode</source>
        <translation>Режим польоту</translation>
    </message>
    <message>
        <source>Mission state</source>
        <translation>Стан місії</translation>
    </message>
    <message>
        <source>Current waypoint</source>
        <translation>Поточна точка маршруту</translation>
    </message>
    <message>
        <source>Waypoints reached</source>
        <translation>Досягнуті точки маршруту</translation>
    </message>
    <message>
        <source>Waypoints on board</source>
        <translation>Точки маршруту на борту</translation>
    </message>
    <message>
        <source>Fence breached</source>
        <translation>Геозону порушено</translation>
    </message>
    <message>
        <source>Fence breaches</source>
        <translation>Порушення геозони</translation>
    </message>
</context>
<context>
    <name>TelemetryPage</name>
    <message>
        <source>Vehicles</source>
        <translation>Апарати</translation>
    </message>
    <message>
        <source>No vehicles. Log in to a server or connect a VCI vehicle.</source>
        <translation>Немає апаратів. Увійдіть на сервер або підключіть апарат VCI.</translation>
    </message>
    <message>
        <source>Command together with the other ticked vehicles</source>
        <translation>Керувати разом з іншими позначеними апаратами</translation>
    </message>
    <message>
        <source>Vehicle %1</source>
        <translation>Апарат %1</translation>
    </message>
    <message>
        <source>A vehicle reached directly over VCI: tcp://host:port or serial:///dev/ttyX?baud=57600</source>
        <translation>Апарат, підключений напряму через VCI: tcp://host:port або serial:///dev/ttyX?baud=57600</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Додати</translation>
    </message>
    <message>
        <source>Fit all</source>
        <translation>Показати всі</translation>
    </message>
    <message>
        <source>Show every vehicle on the map</source>
        <translation>Показати всі апарати на карті</translation>
    </message>
    <message>
        <source>Follow</source>
        <translation>Стежити</translation>
    </message>
    <message>
        <source>Keep the chosen vehicle in the middle of the map</source>
        <translation>Тримати вибраний апарат у центрі карти</translation>
    </message>
    <message>
        <source>Fly %1 to %2?</source>
        <translation>Летіти %1 до %2?</translation>
    </message>
    <message>
        <source>Plot this field too</source>
        <translation>Додати це поле на графік</translation>
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
        <translation>Прибрати з графіка</translation>
    </message>
    <message>
        <source>All vehicles</source>
        <translation>Усі апарати</translation>
    </message>
    <message>
        <source>Compare these fields across every vehicle</source>
        <translation>Порівняти ці поля для всіх апаратів</translation>
    </message>
    <message>
        <source>Video</source>
        <translation>Відео</translation>
    </message>
    <message>
        <source>Show the chosen vehicle&apos;s video over the map</source>
        <translation>Показати відео вибраного апарата над картою</translation>
    </message>
</context>
<context>
    <name>TerrainFollow</name>
    <message>
        <source>Waiting for terrain data from %1</source>
        <translation>Очікування даних рельєфу від %1</translation>
    </message>
    <message>
        <source>No terrain data %1 m along the pass (tried: %2): terrain following needs the ground everywhere</source>
        <translation>Немає даних рельєфу на %1 m уздовж проходу (спробувано: %2): для польоту з обгинанням рельєфу потрібні дані всюди</translation>
    </message>
</context>
<context>
    <name>TerrainProfile</name>
    <message>
        <source>%1, point %2</source>
        <translation>%1, точка %2</translation>
    </message>
    <message>
        <source>Waypoint %1</source>
        <translation>Точка %1</translation>
    </message>
    <message>
        <source>Leg %1 (%2 → %3)</source>
        <translation>Ділянка %1 (%2 → %3)</translation>
    </message>
</context>
<context>
    <name>TerrainRule</name>
    <message>
        <source>Waypoint %1</source>
        <translation>Точка %1</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>з %1 по %2</translation>
    </message>
    <message>
        <source>%1 m above the ground</source>
        <translation>%1 m над поверхнею</translation>
    </message>
    <message>
        <source>%1 m below the ground</source>
        <translation>%1 m під поверхнею</translation>
    </message>
    <message>
        <source> (too low from %1 m to %2 m along it)</source>
        <translation> (занизько від %1 m до %2 m уздовж неї)</translation>
    </message>
    <message>
        <source>%1 flies %2 at %3 m along it%4, closer than the safe distance of %5 m.</source>
        <translation>%1 пролітає %2 на %3 m уздовж неї%4, ближче за безпечну відстань %5 m.</translation>
    </message>
    <message>
        <source>%1: no terrain data from %2 m to %3 m along it</source>
        <translation>%1: немає даних рельєфу від %2 m до %3 m уздовж неї</translation>
    </message>
    <message>
        <source>No terrain data from %1 m along %2 to %3 m along %4</source>
        <translation>Немає даних рельєфу від %1 m уздовж %2 до %3 m уздовж %4</translation>
    </message>
    <message>
        <source>%1 (tried: %2); the clearance there is not checked.</source>
        <translation>%1 (спробувано: %2); запас висоти там не перевіряється.</translation>
    </message>
    <message>
        <source>%1: the altitude is above home, but there is no terrain data at home (tried: %2), so the height above sea level is unknown.</source>
        <translation>%1: висоту задано над точкою старту, але для точки старту немає даних рельєфу (спробувано: %2), тож висота над рівнем моря невідома.</translation>
    </message>
    <message>
        <source>%1: the altitude is above the ground, but there is no terrain data there (tried: %2), so the height above sea level is unknown.</source>
        <translation>%1: висоту задано над землею, але там немає даних рельєфу (спробувано: %2), тож висота над рівнем моря невідома.</translation>
    </message>
    <message>
        <source>%1 flies up to %2 m above the ground at %3 m along it; the open category allows %4 m above the surface.</source>
        <translation>%1 летить до %2 m над землею на %3 m від її початку; відкрита категорія дозволяє %4 m над поверхнею.</translation>
    </message>
</context>
<context>
    <name>TileArea</name>
    <message>
        <source>The area is not a valid latitude/longitude box (south %1, west %2, north %3, east %4).</source>
        <translation>Район не є коректним прямокутником широти/довготи (південь %1, захід %2, північ %3, схід %4).</translation>
    </message>
    <message>
        <source>An area needs at least three corners (it has %1).</source>
        <translation>Районові потрібно щонайменше три кути (має %1).</translation>
    </message>
    <message>
        <source>Corner %1 of the area is not a latitude/longitude (%2, %3).</source>
        <translation>Кут %1 району не є широтою/довготою (%2, %3).</translation>
    </message>
    <message>
        <source>The area&apos;s edge from corner %1 crosses the antimeridian: draw it as two areas.</source>
        <translation>Ребро району від кута %1 перетинає антимеридіан: намалюйте його як два райони.</translation>
    </message>
    <message>
        <source>The area&apos;s edges from corner %1 and corner %2 cross: draw it without crossing.</source>
        <translation>Сторони області від кута %1 і кута %2 перетинаються: намалюйте її без перетинів.</translation>
    </message>
</context>
<context>
    <name>TileResponse</name>
    <message>
        <source>larger than %1 MiB: not read</source>
        <translation>більше за %1 МіБ: не прочитано</translation>
    </message>
</context>
<context>
    <name>TileUrlTemplate</name>
    <message>
        <source>No tile URL template is set.</source>
        <translation>Шаблон URL тайлів не задано.</translation>
    </message>
    <message>
        <source>The tile URL template is not a valid URL: %1</source>
        <translation>Шаблон URL тайлів не є коректним URL: %1</translation>
    </message>
    <message>
        <source>The tile URL template must start with http://, https:// or file://.</source>
        <translation>Шаблон URL тайлів має починатися з http://, https:// або file://.</translation>
    </message>
    <message>
        <source>The tile URL template needs {z}, {x} and {y} (or {-y}).</source>
        <translation>Шаблону URL тайлів потрібні {z}, {x} і {y} (або {-y}).</translation>
    </message>
</context>
<context>
    <name>TlsServerIdentity</name>
    <message>
        <source>this Qt has no TLS backend (%1)</source>
        <translation>у цій збірці Qt немає TLS-бекенда (%1)</translation>
    </message>
    <message>
        <source>%1 holds no PEM certificate</source>
        <translation>%1 не містить сертифіката PEM</translation>
    </message>
    <message>
        <source>%1 holds no unencrypted PEM RSA or EC private key</source>
        <translation>%1 не містить незашифрованого приватного ключа PEM (RSA чи EC)</translation>
    </message>
</context>
<context>
    <name>TlsVerdict</name>
    <message>
        <source>%1 sent no certificate</source>
        <translation>%1 не надіслав сертифіката</translation>
    </message>
    <message>
        <source>the pinned fingerprint for %1 is not a SHA-256 fingerprint (64 hex digits): %2</source>
        <translation>закріплений відбиток для %1 не є відбитком SHA-256 (64 шістнадцяткові цифри): %2</translation>
    </message>
    <message>
        <source>%1 showed a certificate that is not the pinned one: pinned SHA-256 %2, shown SHA-256 %3</source>
        <translation>%1 показав не закріплений сертифікат: закріплений SHA-256 %2, показаний SHA-256 %3</translation>
    </message>
    <message>
        <source>the certificate of %1 has changed since it was first trusted: remembered SHA-256 %2, now SHA-256 %3. Someone may be in between; if the server&apos;s certificate was replaced on purpose, forget the remembered one</source>
        <translation>сертифікат %1 змінився відтоді, як йому вперше довірили: збережений SHA-256 %2, тепер SHA-256 %3. Можливо, хтось є посередині; якщо сертифікат сервера замінили навмисно, забудьте збережений</translation>
    </message>
    <message>
        <source>the certificate of %1 (SHA-256 %2) is not trusted by this system (%3), and there is no pinned or remembered one</source>
        <translation>ця система не довіряє сертифікату %1 (SHA-256 %2) (%3), а закріпленого чи збереженого немає</translation>
    </message>
</context>
<context>
    <name>UploadQuestion</name>
    <message>
        <source>Upload the route?</source>
        <translation>Завантажити маршрут?</translation>
    </message>
    <message>
        <source>Upload without saving</source>
        <translation>Завантажити без збереження</translation>
    </message>
    <message>
        <source>Upload</source>
        <translation>Завантажити</translation>
    </message>
    <message>
        <source>Save and upload</source>
        <translation>Зберегти й завантажити</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Скасувати</translation>
    </message>
</context>
<context>
    <name>UploadReview</name>
    <message>
        <source>%1 Fix it before %2.</source>
        <translation>%1 Виправте це перед %2.</translation>
    </message>
    <message numerus="yes">
        <source>%1 (and %n more error(s)) Fix them before %2.</source>
        <translation>
            <numerusform>%1 (і ще помилок: %n) Виправте їх перед %2.</numerusform>
            <numerusform>%1 (і ще помилок: %n) Виправте їх перед %2.</numerusform>
            <numerusform>%1 (і ще помилок: %n) Виправте їх перед %2.</numerusform>
        </translation>
    </message>
    <message>
        <source>Upload</source>
        <translation>Завантажити</translation>
    </message>
    <message>
        <source>uploading</source>
        <translation>завантаженням</translation>
    </message>
    <message>
        <source>The route has edits that are not saved: the vehicle would fly what is on screen, not what the server holds.</source>
        <translation>Маршрут має незбережені зміни: апарат полетить те, що на екрані, а не те, що зберігає сервер.</translation>
    </message>
    <message numerus="yes">
        <source>The route has %n warning(s):</source>
        <translation>
            <numerusform>Маршрут має попередження (%n):</numerusform>
            <numerusform>Маршрут має попередження (%n):</numerusform>
            <numerusform>Маршрут має попередження (%n):</numerusform>
        </translation>
    </message>
    <message>
        <source>Upload to %1?</source>
        <translation>Завантажити в %1?</translation>
    </message>
    <message>
        <source>Saving</source>
        <translation>Збереження</translation>
    </message>
    <message>
        <source>saving</source>
        <translation>збереженням</translation>
    </message>
</context>
<context>
    <name>UploadedFenceAlerts</name>
    <message>
        <source>route fence</source>
        <translation>геозона маршруту</translation>
    </message>
</context>
<context>
    <name>ValidationGate</name>
    <message numerus="yes">
        <source>%1 refused: the route has %n validation error(s). %2 Fix them, or override explicitly.</source>
        <translation>
            <numerusform>%1 відхилено: маршрут має %n помилку перевірки. %2 Виправте їх або явно скасуйте перевірку.</numerusform>
            <numerusform>%1 відхилено: маршрут має %n помилки перевірки. %2 Виправте їх або явно скасуйте перевірку.</numerusform>
            <numerusform>%1 відхилено: маршрут має %n помилок перевірки. %2 Виправте їх або явно скасуйте перевірку.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>VciConnection</name>
    <message>
        <source>the connection to the vehicle was closed</source>
        <translation>з’єднання з апаратом закрито</translation>
    </message>
    <message>
        <source>the device was closed</source>
        <translation>пристрій закрито</translation>
    </message>
    <message>
        <source>the device was destroyed</source>
        <translation>пристрій знищено</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid VCI URI</source>
        <translation>«%1» не є коректним URI VCI</translation>
    </message>
    <message>
        <source>a ground station does not send NOTIFY</source>
        <translation>наземна станція не надсилає NOTIFY</translation>
    </message>
    <message>
        <source>not connected to the vehicle</source>
        <translation>немає підключення до апарата</translation>
    </message>
    <message>
        <source>no answer in time (it waited behind other requests)</source>
        <translation>немає відповіді вчасно (запит чекав за іншими запитами)</translation>
    </message>
    <message>
        <source>writing to the vehicle failed: %1</source>
        <translation>не вдалося записати в апарат: %1</translation>
    </message>
    <message>
        <source>the vehicle sent an answer (%1) to no request</source>
        <translation>апарат надіслав відповідь (%1) без запиту</translation>
    </message>
    <message>
        <source>unreadable message from the vehicle at byte %1: %2</source>
        <translation>нечитабельне повідомлення від апарата на байті %1: %2</translation>
    </message>
    <message>
        <source>%1: the vehicle answered %2 %3</source>
        <translation>%1: апарат відповів %2 %3</translation>
    </message>
    <message>
        <source>the vehicle did not answer in time</source>
        <translation>апарат не відповів вчасно</translation>
    </message>
</context>
<context>
    <name>VciEndpoint</name>
    <message>
        <source>&quot;%1&quot; is not a URL: %2</source>
        <translation>«%1» не є URL: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names no serial device</source>
        <translation>«%1» не називає послідовного пристрою</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: unknown serial setting &quot;%2&quot; (baud, databits, parity, stopbits, flow)</source>
        <translation>«%1»: невідоме налаштування послідовного порту «%2» (baud, databits, parity, stopbits, flow)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2=%3 is not a valid value</source>
        <translation>«%1»: %2=%3 — некоректне значення</translation>
    </message>
    <message>
        <source>&quot;%1&quot; needs a host and a port: %2://host:port</source>
        <translation>«%1» потребує вузла й порту: %2://вузол:порт</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: unknown setting &quot;%2&quot; (vci+tls:// knows sha256=)</source>
        <translation>«%1»: невідомий параметр «%2» (vci+tls:// знає sha256=)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: sha256=%2 is not a SHA-256 fingerprint (64 hex digits)</source>
        <translation>«%1»: sha256=%2 не є відбитком SHA-256 (64 шістнадцяткові цифри)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: use tcp://host:port, vci+tls://host:port or serial:/dev/name</source>
        <translation>«%1»: використовуйте tcp://вузол:порт, vci+tls://вузол:порт або serial:/dev/назва</translation>
    </message>
</context>
<context>
    <name>VciFenceBuilder</name>
    <message>
        <source>zone &apos;%1&apos;: its AGL limits need the ground under it, which no terrain source has; a vehicle cannot be given it</source>
        <translation>зона «%1»: її межі AGL потребують рельєфу під нею, якого немає в жодному джерелі рельєфу; апаратові її не можна передати</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: no ground under it, so its AGL limits were dropped (the vehicle keeps out of the whole column)</source>
        <translation>зона «%1»: під нею немає даних рельєфу, тому її межі AGL відкинуто (апарат не заходить у весь стовп)</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: over ground from %2 to %3 m its AGL limits leave no room in AMSL</source>
        <translation>зона «%1»: над рельєфом від %2 до %3 m її межі AGL не лишають простору в AMSL</translation>
    </message>
    <message>
        <source>%1 (hole %2)</source>
        <translation>%1 (отвір %2)</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: its holes are closed on the vehicle (a fence polygon has none)</source>
        <translation>зона «%1»: її отвори на апараті закрито (полігон геозони не має отворів)</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: a cone that narrows to a point cannot keep a vehicle in</source>
        <translation>зона «%1»: конус, що звужується в точку, не може утримати апарат усередині</translation>
    </message>
    <message>
        <source>zone &apos;%1&apos;: its cone is a cylinder of radius %2 m on the vehicle</source>
        <translation>зона «%1»: на апараті її конус — циліндр радіусом %2 m</translation>
    </message>
    <message>
        <source>route fence</source>
        <translation>геозона маршруту</translation>
    </message>
    <message>
        <source>the fence cannot be sent: %1</source>
        <translation>геозону не можна надіслати: %1</translation>
    </message>
    <message numerus="yes">
        <source>fence: %1 of the route&apos;s own, %n airspace zone(s) near it; on a breach the vehicle will %2</source>
        <translation>
            <numerusform>геозона: власних зон маршруту — %1, а також %n зона повітряного простору поруч; у разі порушення апарат виконає: %2</numerusform>
            <numerusform>геозона: власних зон маршруту — %1, а також %n зони повітряного простору поруч; у разі порушення апарат виконає: %2</numerusform>
            <numerusform>геозона: власних зон маршруту — %1, а також %n зон повітряного простору поруч; у разі порушення апарат виконає: %2</numerusform>
        </translation>
    </message>
    <message>
        <source>return home</source>
        <translation>повернення додому</translation>
    </message>
    <message>
        <source>land</source>
        <translation>посадка</translation>
    </message>
    <message>
        <source>hold</source>
        <translation>утримання</translation>
    </message>
    <message>
        <source>the fence cannot be made: its zones are not the airspace&apos;s</source>
        <translation>геозону не можна створити: її зони не з повітряного простору</translation>
    </message>
</context>
<context>
    <name>VciMissionPlanner</name>
    <message>
        <source>the route has no waypoints to fly</source>
        <translation>маршрут не має точок для польоту</translation>
    </message>
</context>
<context>
    <name>VciTransport</name>
    <message>
        <source>closed by the operator</source>
        <translation>закрито оператором</translation>
    </message>
    <message>
        <source>reconnecting at the operator&apos;s request</source>
        <translation>перепідключення на запит оператора</translation>
    </message>
    <message>
        <source>the vehicle closed the connection</source>
        <translation>апарат закрив з’єднання</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <translation>не вдається відкрити %1: %2</translation>
    </message>
    <message>
        <source>not connected over TLS: %1</source>
        <translation>немає з’єднання через TLS: %1</translation>
    </message>
</context>
<context>
    <name>VciVehicleLink</name>
    <message>
        <source>connection to %1 lost: %2</source>
        <translation>з’єднання з %1 втрачено: %2</translation>
    </message>
    <message>
        <source>disconnected by the operator</source>
        <translation>відключено оператором</translation>
    </message>
    <message>
        <source>left its fence &apos;%1&apos;</source>
        <translation>покинув свою геозону «%1»</translation>
    </message>
    <message>
        <source>entered the exclusion zone &apos;%1&apos;</source>
        <translation>увійшов у заборонну зону «%1»</translation>
    </message>
    <message>
        <source>returning home</source>
        <extracomment>What a vehicle does after a fence breach: &quot;fence breach: left its fence &apos;A&apos;; returning home&quot;.</extracomment>
        <translation>повертається додому</translation>
    </message>
    <message>
        <source>action unknown</source>
        <extracomment>After a fence breach, the vehicle named no action: &quot;fence breach: left its fence &apos;A&apos;; action unknown&quot;.</extracomment>
        <translation>дія невідома</translation>
    </message>
    <message>
        <source>fence breach: %1; %2</source>
        <translation>порушення геозони: %1; %2</translation>
    </message>
    <message>
        <source>the ground under the route did not arrive from %1 in %2 s</source>
        <translation>дані рельєфу під маршрутом не надійшли від %1 за %2 s</translation>
    </message>
    <message>
        <source>the vehicle refused the fence: %1</source>
        <translation>апарат відхилив геозону: %1</translation>
    </message>
    <message>
        <source>the fence could not be read back: %1</source>
        <translation>не вдалося зчитати геозону назад: %1</translation>
    </message>
    <message>
        <source>the vehicle&apos;s fence cannot be read: %1</source>
        <translation>не вдається прочитати геозону апарата: %1</translation>
    </message>
    <message>
        <source>the vehicle holds another fence than the one sent (%1 items sent, %2 held)</source>
        <translation>на борту апарата інша геозона, ніж надіслана (надіслано елементів: %1, на борту: %2)</translation>
    </message>
    <message>
        <source>the vehicle&apos;s mission cannot be read: %1</source>
        <translation>не вдається прочитати місію апарата: %1</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a parameter name</source>
        <translation>«%1» не є назвою параметра</translation>
    </message>
    <message>
        <source>landing</source>
        <extracomment>What a vehicle does after a fence breach: &quot;fence breach: left its fence &apos;A&apos;; landing&quot;.</extracomment>
        <translation>сідає</translation>
    </message>
    <message>
        <source>holding</source>
        <extracomment>What a vehicle does after a fence breach: &quot;fence breach: left its fence &apos;A&apos;; holding&quot;.</extracomment>
        <translation>утримує позицію</translation>
    </message>
    <message>
        <source>the fence cannot be made: this link was given no fence builder</source>
        <translation>геозону не можна створити: цьому з’єднанню не надано побудовника геозон</translation>
    </message>
    <message>
        <source>%1: first secure connection; its certificate is now trusted and remembered. Compare its SHA-256 fingerprint with the vehicle&apos;s: %2</source>
        <translation>%1: перше захищене з’єднання; його сертифікату тепер довіряють, і його збережено. Порівняйте його відбиток SHA-256 з відбитком апарата: %2</translation>
    </message>
    <message>
        <source>a photo report was not understood: %1</source>
        <translation>повідомлення про фото незрозуміле: %1</translation>
    </message>
</context>
<context>
    <name>Vehicle</name>
    <message>
        <source>mode %1</source>
        <translation>режим %1</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a flight mode</source>
        <translation>«%1» не є режимом польоту</translation>
    </message>
    <message>
        <source>takeoff to %1 m</source>
        <translation>зліт на %1 m</translation>
    </message>
    <message>
        <source>return home</source>
        <translation>повернення додому</translation>
    </message>
</context>
<context>
    <name>VerticalDatum</name>
    <message>
        <source>ellipsoidal (%1)</source>
        <translation>еліпсоїдальні (%1)</translation>
    </message>
    <message>
        <source>orthometric (%1)</source>
        <translation>ортометричні (%1)</translation>
    </message>
    <message>
        <source>not stated</source>
        <translation>не вказано</translation>
    </message>
</context>
<context>
    <name>VideoPanel</name>
    <message>
        <source>rtsp://, udp://:5600 or an .sdp file</source>
        <translation>rtsp://, udp://:5600 або файл .sdp</translation>
    </message>
    <message>
        <source>This vehicle&apos;s video: empty plays the stream the vehicle publishes; a URL typed here overrides it and is remembered.</source>
        <translation>Відео цього апарата: порожньо — потік, який публікує апарат; URL, введена тут, замінює його й запам’ятовується.</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Записати</translation>
    </message>
    <message>
        <source>Recording to %1</source>
        <translation>Запис у %1</translation>
    </message>
    <message>
        <source>Record this video as received, beside the flight log</source>
        <translation>Записати це відео як отримано, поруч із журналом польоту</translation>
    </message>
    <message>
        <source>Map</source>
        <translation>Карта</translation>
    </message>
    <message>
        <source>Swap</source>
        <translation>Поміняти</translation>
    </message>
</context>
<context>
    <name>VideoSource</name>
    <message>
        <source>latency &apos;%1&apos;: expected milliseconds from 0 to 10000</source>
        <translation>затримка «%1»: очікуються мілісекунди від 0 до 10000</translation>
    </message>
    <message>
        <source>codec &apos;%1&apos;: expected h264 or h265</source>
        <translation>кодек «%1»: очікується h264 або h265</translation>
    </message>
    <message>
        <source>payload &apos;%1&apos;: expected a dynamic RTP payload type from 96 to 127</source>
        <translation>payload «%1»: очікується динамічний тип RTP від 96 до 127</translation>
    </message>
    <message>
        <source>unknown option &apos;%1&apos;</source>
        <translation>невідомий параметр «%1»</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an IP address to listen on</source>
        <translation>«%1» — не IP-адреса для прослуховування</translation>
    </message>
    <message>
        <source>port %1 is out of range</source>
        <translation>порт %1 поза діапазоном</translation>
    </message>
    <message>
        <source>an RTSP URL needs a host: rtsp://host:8554/path</source>
        <translation>RTSP-URL потрібен хост: rtsp://host:8554/path</translation>
    </message>
    <message>
        <source>port 0 is out of range</source>
        <translation>порт 0 поза діапазоном</translation>
    </message>
    <message>
        <source>SDP file %1: %2</source>
        <translation>Файл SDP %1: %2</translation>
    </message>
    <message>
        <source>RTSP over TCP %1</source>
        <translation>RTSP через TCP %1</translation>
    </message>
    <message>
        <source>RTSP %1</source>
        <translation>RTSP %1</translation>
    </message>
    <message>
        <source>RTP/UDP %1 port %2</source>
        <translation>RTP/UDP %1 порт %2</translation>
    </message>
    <message>
        <source>MPEG-TS/UDP port %1</source>
        <translation>MPEG-TS/UDP порт %1</translation>
    </message>
    <message>
        <source>no video URL</source>
        <translation>немає URL відео</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a URL</source>
        <translation>«%1» — не URL</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a video URL Sortie plays: use rtsp://, rtspt://, udp://, udp+ts:// or an .sdp file</source>
        <translation>«%1» — не URL відео, яку відтворює Sortie: використовуйте rtsp://, rtspt://, udp://, udp+ts:// або файл .sdp</translation>
    </message>
    <message>
        <source>SDP file %1 cannot be read as SDP</source>
        <translation>Файл SDP %1 не читається як SDP</translation>
    </message>
    <message>
        <source>SDP file %1: port %2 is out of range</source>
        <translation>Файл SDP %1: порт %2 поза діапазоном</translation>
    </message>
    <message>
        <source>SDP file %1: the video has no payload type</source>
        <translation>Файл SDP %1: відео не має типу payload</translation>
    </message>
    <message>
        <source>SDP file %1: payload type %2 is not a dynamic one (96 to 127)</source>
        <translation>Файл SDP %1: тип payload %2 не динамічний (96–127)</translation>
    </message>
    <message>
        <source>SDP file %1: no rtpmap for payload %2</source>
        <translation>Файл SDP %1: немає rtpmap для payload %2</translation>
    </message>
    <message>
        <source>SDP file %1: the video is %2, not H.264 or H.265</source>
        <translation>Файл SDP %1: відео — %2, а не H.264 чи H.265</translation>
    </message>
    <message>
        <source>SDP file %1 describes no video</source>
        <translation>Файл SDP %1 не описує відео</translation>
    </message>
</context>
<context>
    <name>WaypointAction</name>
    <message>
        <source>Wait for operator</source>
        <translation>Чекати на оператора</translation>
    </message>
    <message>
        <source>Wait %1 s</source>
        <translation>Чекати %1 s</translation>
    </message>
    <message>
        <source>Heading %1°%2</source>
        <translation>Курс %1°%2</translation>
    </message>
    <message>
        <source> from course</source>
        <translation> від напрямку руху</translation>
    </message>
    <message>
        <source>Look at %1, %2</source>
        <translation>Дивитися на %1, %2</translation>
    </message>
    <message>
        <source>Take photo</source>
        <translation>Зробити фото</translation>
    </message>
    <message>
        <source>Start video</source>
        <translation>Почати відео</translation>
    </message>
    <message>
        <source>Stop video</source>
        <translation>Зупинити відео</translation>
    </message>
    <message>
        <source>Toggle video</source>
        <translation>Перемкнути відео</translation>
    </message>
    <message>
        <source>Photo every %1 s</source>
        <translation>Фото кожні %1 s</translation>
    </message>
    <message>
        <source>Photo every %1 m</source>
        <translation>Фото кожні %1 m</translation>
    </message>
    <message>
        <source>Stop photos</source>
        <translation>Зупинити фото</translation>
    </message>
    <message>
        <source>Panorama %1°</source>
        <translation>Панорама %1°</translation>
    </message>
    <message>
        <source>tilt %1°</source>
        <translation>нахил %1°</translation>
    </message>
    <message>
        <source>roll %1°</source>
        <translation>крен %1°</translation>
    </message>
    <message>
        <source>yaw %1°</source>
        <translation>рискання %1°</translation>
    </message>
    <message>
        <source>zoom %1</source>
        <translation>масштаб %1</translation>
    </message>
    <message>
        <source>Gimbal (nothing set)</source>
        <translation>Підвіс (нічого не задано)</translation>
    </message>
</context>
<context>
    <name>WaypointTable</name>
    <message numerus="yes">
        <source>%n selected:</source>
        <translation>
            <numerusform>Вибрано %n:</numerusform>
            <numerusform>Вибрано %n:</numerusform>
            <numerusform>Вибрано %n:</numerusform>
        </translation>
    </message>
    <message>
        <source>alt m</source>
        <translation>вис. m</translation>
    </message>
    <message>
        <source>Set</source>
        <translation>Задати</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>Altitude above ground (AGL) or above mean sea level (AMSL)</source>
        <translation>Висота над поверхнею (AGL) або над середнім рівнем моря (AMSL)</translation>
    </message>
    <message>
        <source>Heights:</source>
        <translation>Висоти:</translation>
    </message>
    <message>
        <source>as set</source>
        <translation>як задано</translation>
    </message>
    <message>
        <source>all AMSL</source>
        <translation>усі AMSL</translation>
    </message>
    <message>
        <source>all AGL</source>
        <translation>усі AGL</translation>
    </message>
    <message>
        <source>AMSL and AGL are converted through the ground under each waypoint</source>
        <translation>AMSL і AGL перераховуються через рельєф під кожною точкою</translation>
    </message>
    <message>
        <source>ground: %1</source>
        <translation>рельєф: %1</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>Latitude</source>
        <translation>Широта</translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation>Довгота</translation>
    </message>
    <message>
        <source>Alt</source>
        <translation>Вис.</translation>
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
        <translation>Тип</translation>
    </message>
    <message>
        <source>Ground</source>
        <translation>Рельєф</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Швидкість</translation>
    </message>
    <message>
        <source>Actions</source>
        <translation>Дії</translation>
    </message>
    <message>
        <source>Area scan</source>
        <translation>Сканування площі</translation>
    </message>
</context>
<context>
    <name>WplFormat</name>
    <message>
        <source>not a waypoint file: expected &quot;QGC WPL 110&quot;, found &quot;%1&quot;</source>
        <translation>не файл точок: очікується &quot;QGC WPL 110&quot;, знайдено «%1»</translation>
    </message>
    <message>
        <source>unsupported waypoint file version &quot;%1&quot;; Sortie reads QGC WPL 110</source>
        <translation>непідтримувана версія файлу точок «%1»; Sortie читає QGC WPL 110</translation>
    </message>
    <message>
        <source>expected 12 tab-separated fields, found %1</source>
        <translation>очікується 12 полів, розділених табуляцією, знайдено %1</translation>
    </message>
    <message>
        <source>field %1 (%2) is not a number: &quot;%3&quot;</source>
        <translation>поле %1 (%2) не є числом: «%3»</translation>
    </message>
    <message>
        <source>field %1 (%2) must be a whole number, found %3</source>
        <translation>поле %1 (%2) має бути цілим числом, знайдено %3</translation>
    </message>
    <message>
        <source>item %1 where item %2 was expected</source>
        <translation>елемент %1 там, де очікувався елемент %2</translation>
    </message>
    <message>
        <source>the home position %1, %2 is not a position</source>
        <translation>точка дому %1, %2 не є позицією</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>файл порожній</translation>
    </message>
    <message>
        <source>the file has no items, not even the home position</source>
        <translation>файл не має елементів, навіть точки дому</translation>
    </message>
    <message>
        <source>The route has no home position: the first point was written as home, at 0 m AMSL.</source>
        <translation>Маршрут не має точки дому: першу точку записано як дім, на 0 m AMSL.</translation>
    </message>
</context>
<context>
    <name>WpmlDocumentReader</name>
    <message>
        <source>malformed XML: %1</source>
        <translation>некоректний XML: %1</translation>
    </message>
    <message>
        <source>%1 is not a number: &quot;%2&quot;</source>
        <translation>%1 не є числом: «%2»</translation>
    </message>
    <message>
        <source>%1 is not a whole number: &quot;%2&quot;</source>
        <translation>%1 не є цілим числом: «%2»</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; (written as &quot;%3&quot;)</source>
        <translation>%1 «%2» (записано як «%3»)</translation>
    </message>
    <message>
        <source>coordinates &quot;%1&quot; are not longitude,latitude in degrees</source>
        <translation>координати «%1» не є longitude,latitude у градусах</translation>
    </message>
    <message>
        <source>a waypoint index is not a whole number</source>
        <translation>індекс точки не є цілим числом</translation>
    </message>
</context>
<context>
    <name>ZipArchive</name>
    <message>
        <source>two of its entries have the same name</source>
        <translation>два його елементи мають однакову назву</translation>
    </message>
    <message>
        <source>its directory and its entries disagree</source>
        <translation>його каталог і елементи не узгоджуються</translation>
    </message>
    <message>
        <source>it has no ZIP directory (truncated, or not a ZIP file)</source>
        <translation>у ньому немає каталогу ZIP (обрізаний або не файл ZIP)</translation>
    </message>
    <message>
        <source>the archive has no end of central directory</source>
        <translation>архів не має кінця центрального каталогу</translation>
    </message>
    <message>
        <source>ZIP64 archives are not read</source>
        <translation>архіви ZIP64 не читаються</translation>
    </message>
    <message>
        <source>a central directory record is damaged at byte %1</source>
        <translation>запис центрального каталогу пошкоджено на байті %1</translation>
    </message>
    <message>
        <source>an entry&apos;s local header lies outside the archive</source>
        <translation>локальний заголовок елемента лежить поза архівом</translation>
    </message>
    <message>
        <source>the entries &quot;%1&quot; and &quot;%2&quot; share bytes in the archive (a ZIP bomb&apos;s trick): not read</source>
        <translation>елементи «%1» і «%2» спільно використовують байти архіву (трюк ZIP-бомби): не прочитано</translation>
    </message>
    <message>
        <source>not a ZIP archive: %1</source>
        <translation>не архів ZIP: %1</translation>
    </message>
    <message>
        <source>not a readable ZIP archive: %1</source>
        <translation>нечитабельний архів ZIP: %1</translation>
    </message>
    <message>
        <source>the archive lists %1 entries, more than the %2 read</source>
        <translation>архів містить елементів: %1, більше за %2, які читаються</translation>
    </message>
    <message>
        <source>the central directory lists %1 entries where libzip read %2</source>
        <translation>центральний каталог містить елементів: %1, а libzip прочитав %2</translation>
    </message>
    <message>
        <source>the archive has no &quot;%1&quot;</source>
        <translation>архів не має «%1»</translation>
    </message>
    <message>
        <source>&quot;%1&quot; would inflate to %2 bytes, more than the %3 read from one entry</source>
        <translation>«%1» розпакувався б до %2 байт, більше за %3, що читаються з одного елемента</translation>
    </message>
    <message>
        <source>reading &quot;%1&quot; would inflate the archive past %2 bytes in all</source>
        <translation>читання «%1» розпакувало б архів понад %2 байт загалом</translation>
    </message>
    <message>
        <source>&quot;%1&quot; claims %2 bytes from %3 compressed, more than %4 times: not inflated</source>
        <translation>«%1» заявляє %2 байт із %3 стиснутих, більш ніж у %4 раз: не розпаковано</translation>
    </message>
    <message>
        <source>&quot;%1&quot; cannot be read: %2</source>
        <translation>«%1» не вдається прочитати: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is damaged: %2</source>
        <translation>«%1» пошкоджено: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; holds a different size than the archive says (%2 bytes)</source>
        <translation>«%1» має інший розмір, ніж вказано в архіві (%2 байт)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is damaged (its CRC does not match)</source>
        <translation>«%1» пошкоджено (його CRC не збігається)</translation>
    </message>
    <message>
        <source>the archive could not be written: %1</source>
        <translation>не вдалося записати архів: %1</translation>
    </message>
    <message>
        <source>the archive could not be written: its bytes could not be read back</source>
        <translation>не вдалося записати архів: його байти не вдалося зчитати назад</translation>
    </message>
</context>
<context>
    <name>Zone</name>
    <message>
        <source>above home</source>
        <translation>над точкою дому</translation>
    </message>
    <message>
        <source>server aerodrome</source>
        <translation>сервер (зона аеродрому)</translation>
    </message>
    <message>
        <source>server custom</source>
        <translation>сервер (власна зона)</translation>
    </message>
    <message>
        <source>vehicle fence</source>
        <translation>геозона апарата</translation>
    </message>
    <message>
        <source>%1 polygon %2</source>
        <translation>%1: полігон %2</translation>
    </message>
    <message>
        <source>%1 circle %2</source>
        <translation>%1: коло %2</translation>
    </message>
</context>
<context>
    <name>ZoneEditor</name>
    <message>
        <source>drawn on the map</source>
        <translation>намальовано на карті</translation>
    </message>
    <message>
        <source>vertex %1</source>
        <translation>вершина %1</translation>
    </message>
</context>
<context>
    <name>ZoneFiles</name>
    <message>
        <source>%1 was left out: %2</source>
        <translation>%1 пропущено: %2</translation>
    </message>
    <message>
        <source>unknown zone file type &quot;.%1&quot; (Sortie reads .plan, .geojson, .json and .kml)</source>
        <translation>невідомий тип файлу зон «.%1» (Sortie читає .plan, .geojson, .json і .kml)</translation>
    </message>
    <message>
        <source>volume %1: %2</source>
        <translation>об’єм %1: %2</translation>
    </message>
    <message>
        <source>%1 zone %2 (&apos;%3&apos;) was left out: %4</source>
        <translation>Зону %1 %2 («%3») пропущено: %4</translation>
    </message>
</context>
<context>
    <name>ZoneLegend</name>
    <message>
        <source>Prohibited</source>
        <translation>Заборонено</translation>
    </message>
    <message>
        <source>Authorisation needed</source>
        <translation>Потрібен дозвіл</translation>
    </message>
    <message>
        <source>Conditions apply</source>
        <translation>Діють умови</translation>
    </message>
    <message>
        <source>Information only</source>
        <translation>Лише інформація</translation>
    </message>
    <message>
        <source>Not in force during the flight</source>
        <translation>Не діє під час польоту</translation>
    </message>
</context>
<context>
    <name>ZonePanel</name>
    <message>
        <source>Load zones</source>
        <translation>Імпорт зон</translation>
    </message>
    <message>
        <source>Zones (*.geojson *.json *.kml *.plan)</source>
        <translation>Зони (*.geojson *.json *.kml *.plan)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Усі файли (*)</translation>
    </message>
    <message>
        <source>Zones (%1)</source>
        <translation>Зони (%1)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Вернути</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Повторити</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Імпорт…</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>Полігон</translation>
    </message>
    <message>
        <source>Click the corners on the map, then Create</source>
        <translation>Клацніть кути на карті, потім «Створити»</translation>
    </message>
    <message>
        <source>Circle</source>
        <translation>Коло</translation>
    </message>
    <message>
        <source>Click the centre on the map; drag its handle for the radius</source>
        <translation>Клацніть центр на карті; тягніть маркер, щоб задати радіус</translation>
    </message>
    <message>
        <source>%1 corners</source>
        <translation>кутів: %1</translation>
    </message>
    <message>
        <source>Create</source>
        <translation>Створити</translation>
    </message>
    <message>
        <source>Checked against the route when ticked</source>
        <translation>Перевіряється щодо маршруту, якщо позначено</translation>
    </message>
    <message>
        <source>%1 · %2 – %3</source>
        <translation>%1 · %2 – %3</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Назва</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Тип</translation>
    </message>
    <message>
        <source>Floor (m)</source>
        <translation>Нижня межа (m)</translation>
    </message>
    <message>
        <source>ground</source>
        <translation>поверхня</translation>
    </message>
    <message>
        <source>Ceiling (m)</source>
        <translation>Верхня межа (m)</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>без обмеження</translation>
    </message>
    <message>
        <source>Above</source>
        <translation>Відносно</translation>
    </message>
    <message>
        <source>Remove zone</source>
        <translation>Видалити зону</translation>
    </message>
    <message>
        <source>Warn within (m)</source>
        <translation>Попереджати за (m)</translation>
    </message>
    <message>
        <source>exclusion</source>
        <translation>заборонна</translation>
    </message>
    <message>
        <source>inclusion</source>
        <translation>дозвільна</translation>
    </message>
    <message>
        <source>HOME</source>
        <translation>ДІМ</translation>
    </message>
    <message>
        <source>Discard copy</source>
        <translation>Відкинути копію</translation>
    </message>
    <message>
        <source>The server&apos;s zone stays as it is</source>
        <translation>Зона сервера лишається без змін</translation>
    </message>
    <message>
        <source>Update on server</source>
        <translation>Оновити на сервері</translation>
    </message>
    <message>
        <source>Send to server</source>
        <translation>Надіслати на сервер</translation>
    </message>
    <message>
        <source>Edit here</source>
        <translation>Редагувати тут</translation>
    </message>
    <message>
        <source>Draw a copy to edit; Update on server stores it</source>
        <translation>Намалювати копію для редагування; «Оновити на сервері» зберігає її</translation>
    </message>
    <message>
        <source>Delete on server</source>
        <translation>Видалити на сервері</translation>
    </message>
    <message>
        <source>Waiting for the server…</source>
        <translation>Очікування сервера…</translation>
    </message>
    <message>
        <source>Delete zone</source>
        <translation>Видалити зону</translation>
    </message>
    <message>
        <source>Delete &apos;%1&apos; on the server, for every operator?</source>
        <translation>Видалити «%1» на сервері для всіх операторів?</translation>
    </message>
    <message>
        <source>Zone feed URL (https://…)</source>
        <translation>URL стрічки зон (https://…)</translation>
    </message>
    <message>
        <source>Fetching…</source>
        <translation>Завантаження…</translation>
    </message>
    <message>
        <source>Fetch</source>
        <translation>Завантажити</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Оновити</translation>
    </message>
    <message>
        <source>Fetch the zone feed again from %1</source>
        <translation>Завантажити стрічку зон знову з %1</translation>
    </message>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>Authorisation reference</source>
        <translation>Номер дозволу</translation>
    </message>
    <message>
        <source>Change</source>
        <translation>Змінити</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Записати</translation>
    </message>
    <message>
        <source>Kept with the route; the check then warns instead of refusing (empty: removed)</source>
        <translation>Зберігається з маршрутом; перевірка тоді попереджає замість відмови (порожньо: видалено)</translation>
    </message>
</context>
<context>
    <name>sortie</name>
    <message>
        <source>Sortie: mission planning and live telemetry for UgCS servers and VCI vehicles.</source>
        <translation>Sortie: планування місій і телеметрія в реальному часі для серверів UgCS та апаратів VCI.</translation>
    </message>
    <message>
        <source>Start the built-in simulator on this computer and connect to it.</source>
        <translation>Запустити вбудований симулятор на цьому комп’ютері й підключитися до нього.</translation>
    </message>
    <message>
        <source>User name to log in with.</source>
        <translation>Ім’я користувача для входу.</translation>
    </message>
    <message>
        <source>Print the start-up time and memory in use, then quit (for benchmarks).</source>
        <translation>Вивести час запуску й використану пам’ять, потім вийти (для бенчмарків).</translation>
    </message>
    <message>
        <source>Folder for autosaved edits (default: the application data folder; also SORTIE_AUTOSAVE_DIR).</source>
        <translation>Тека для автозбережених змін (типово: тека даних застосунку; також SORTIE_AUTOSAVE_DIR).</translation>
    </message>
    <message>
        <source>An ADS-B receiver&apos;s SBS-1 feed for manned traffic, as dump1090 serves it (port 30003); also the setting traffic/sbsAddress.</source>
        <translation>Потік SBS-1 приймача ADS-B для пілотованих повітряних суден, як його віддає dump1090 (порт 30003); також налаштування traffic/sbsAddress.</translation>
    </message>
    <message>
        <source>--demo with only the server&apos;s three vehicles: &quot;parked&quot; (nothing moves) or &quot;flying&quot; (one flies, followed in the fly view); for benchmarks.</source>
        <translation>--demo лише з трьома апаратами сервера: &quot;parked&quot; (ніщо не рухається) або &quot;flying&quot; (один летить, за ним стежить сторінка телеметрії); для бенчмарків.</translation>
    </message>
    <message>
        <source>A DEM for the terrain: any raster GDAL reads (GeoTIFF, COG, Copernicus DEM, .hgt, ...) or a folder of them, asked before the server (also the setting terrain/demFolder).</source>
        <translation>DEM для рельєфу: будь-який растр, який читає GDAL (GeoTIFF, COG, Copernicus DEM, .hgt, ...), або тека з ними; запитується раніше за сервер (також налаштування terrain/demFolder).</translation>
    </message>
    <message>
        <source>UgCS server to connect to: host:port, or tls://host:port over TLS (a server behind a TLS terminator).</source>
        <translation>Сервер UgCS для підключення: вузол:порт або tls://вузол:порт через TLS (сервер за TLS-термінатором).</translation>
    </message>
    <message>
        <source>With --server tls://: the only certificate the server may show, as its SHA-256 fingerprint or a PEM file; remembered for that server.</source>
        <translation>З --server tls://: єдиний сертифікат, який може показати сервер, як відбиток SHA-256 або файл PEM; зберігається для цього сервера.</translation>
    </message>
    <message>
        <source>Connect a vehicle directly over VCI: tcp://host:port, vci+tls://host:port[?sha256=FINGERPRINT] or serial:///dev/ttyX?baud=57600.</source>
        <translation>Підключити апарат напряму через VCI: tcp://вузол:порт, vci+tls://вузол:порт[?sha256=ВІДБИТОК] або serial:///dev/ttyX?baud=57600.</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::Airspace</name>
    <message>
        <source>Reason: %1</source>
        <translation>Причина: %1</translation>
    </message>
    <message>
        <source>When: %1</source>
        <translation>Коли: %1</translation>
    </message>
    <message>
        <source>Not in force during the planned flight.</source>
        <translation>Не діє під час запланованого польоту.</translation>
    </message>
    <message>
        <source>Authority: %1</source>
        <translation>Орган: %1</translation>
    </message>
    <message>
        <source>%1: fetched from %2 %3</source>
        <translation>%1: завантажено з %2 %3</translation>
    </message>
    <message>
        <source>%1: a file changed %2</source>
        <translation>%1: файл, змінений %2</translation>
    </message>
    <message>
        <source>Some zone data is older than a week: fetch it or load it again before you fly.</source>
        <translation>Деякі дані зон старші за тиждень: завантажте їх знову перед польотом.</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ServerZones</name>
    <message>
        <source>Zones across the ±180° meridian are not supported; the view was not asked about.</source>
        <translation>Зони через меридіан ±180° не підтримуються; запит для цієї області не надсилався.</translation>
    </message>
    <message>
        <source>The server&apos;s no-fly zones could not be read: %1</source>
        <translation>Не вдалося прочитати заборонені зони сервера: %1</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not saved: not connected to the server.</source>
        <translation>Зону «%1» не збережено: немає підключення до сервера.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; cannot be saved on the server: %2.</source>
        <translation>Зону «%1» не можна зберегти на сервері: %2.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not saved: %2</source>
        <translation>Зону «%1» не збережено: %2</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not saved: it is locked (%2)</source>
        <translation>Зону «%1» не збережено: її заблоковано (%2)</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was saved, but the server&apos;s answer cannot be read back: %2</source>
        <translation>Зону «%1» збережено, але не вдається прочитати відповідь сервера: %2</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: it is not on the server.</source>
        <translation>Зону «%1» не видалено: її немає на сервері.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: aerodrome zones are the server&apos;s own.</source>
        <translation>Зону «%1» не видалено: зони аеродромів належать серверу.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: not connected to the server.</source>
        <translation>Зону «%1» не видалено: немає підключення до сервера.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: it is locked (%2)</source>
        <translation>Зону «%1» не видалено: її заблоковано (%2)</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was not deleted: %2</source>
        <translation>Зону «%1» не видалено: %2</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneAlertMonitor</name>
    <message>
        <source>%1 is inside &apos;%2&apos;</source>
        <translation>%1 усередині «%2»</translation>
    </message>
    <message>
        <source>%1 enters &apos;%2&apos;%3</source>
        <translation>%1 входить у «%2»%3</translation>
    </message>
    <message>
        <source>%1 is outside &apos;%2&apos;</source>
        <translation>%1 поза «%2»</translation>
    </message>
    <message>
        <source>%1 leaves &apos;%2&apos;%3</source>
        <translation>%1 виходить із «%2»%3</translation>
    </message>
    <message>
        <source> (its height there is unknown)</source>
        <translation> (його висота там невідома)</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneEditor</name>
    <message>
        <source>A zone needs at least three corners.</source>
        <translation>Зоні потрібно щонайменше три кути.</translation>
    </message>
    <message>
        <source>This polygon cannot be a zone: %1</source>
        <translation>Цей полігон не може бути зоною: %1</translation>
    </message>
    <message>
        <source>Draw zone</source>
        <translation>Намалювати зону</translation>
    </message>
    <message>
        <source>A circular zone needs a centre and a radius above 0 m.</source>
        <translation>Круговій зоні потрібні центр і радіус більше 0 m.</translation>
    </message>
    <message>
        <source>Draw circular zone</source>
        <translation>Намалювати кругову зону</translation>
    </message>
    <message>
        <source>There is no drawn zone %1.</source>
        <translation>Немає намальованої зони %1.</translation>
    </message>
    <message>
        <source>Remove zone</source>
        <translation>Видалити зону</translation>
    </message>
    <message>
        <source>That is not a position.</source>
        <translation>Це не позиція.</translation>
    </message>
    <message>
        <source>A circle has only its centre to move.</source>
        <translation>У кола можна пересунути лише центр.</translation>
    </message>
    <message>
        <source>The zone has no corner %1.</source>
        <translation>Зона не має кута %1.</translation>
    </message>
    <message>
        <source>Move zone corner</source>
        <translation>Пересунути кут зони</translation>
    </message>
    <message>
        <source>A corner can be added only to a polygon, on one of its edges.</source>
        <translation>Кут можна додати лише до полігона, на одному з його ребер.</translation>
    </message>
    <message>
        <source>Add zone corner</source>
        <translation>Додати кут зони</translation>
    </message>
    <message>
        <source>A zone keeps at least three corners.</source>
        <translation>Зона зберігає щонайменше три кути.</translation>
    </message>
    <message>
        <source>Remove zone corner</source>
        <translation>Видалити кут зони</translation>
    </message>
    <message>
        <source>The radius must be above 0 m.</source>
        <translation>Радіус має бути більше 0 m.</translation>
    </message>
    <message>
        <source>Only a circular zone has a radius.</source>
        <translation>Радіус має лише кругова зона.</translation>
    </message>
    <message>
        <source>Zone radius</source>
        <translation>Радіус зони</translation>
    </message>
    <message>
        <source>A zone needs a name.</source>
        <translation>Зоні потрібна назва.</translation>
    </message>
    <message>
        <source>Rename zone</source>
        <translation>Перейменувати зону</translation>
    </message>
    <message>
        <source>A zone is an exclusion or an inclusion zone, not &quot;%1&quot;.</source>
        <translation>Зона може бути лише exclusion (заборонна) або inclusion (дозвільна), а не «%1».</translation>
    </message>
    <message>
        <source>Zone kind</source>
        <translation>Тип зони</translation>
    </message>
    <message>
        <source>Heights are AMSL, AGL or HOME, not &quot;%1&quot;.</source>
        <translation>Висоти задаються як AMSL, AGL або HOME, а не «%1».</translation>
    </message>
    <message>
        <source>A floor or ceiling is a number of metres, or empty.</source>
        <translation>Нижня чи верхня межа — це число метрів або порожнє поле.</translation>
    </message>
    <message>
        <source>The ceiling (%1 m) must be above the floor (%2 m).</source>
        <translation>Верхня межа (%1 m) має бути вище нижньої (%2 m).</translation>
    </message>
    <message>
        <source>Zone floor and ceiling</source>
        <translation>Нижня й верхня межі зони</translation>
    </message>
    <message>
        <source>The zone would not be a valid polygon: %1</source>
        <translation>Зона не була б коректним полігоном: %1</translation>
    </message>
    <message>
        <source>Zone %1</source>
        <translation>Зона %1</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneFeed</name>
    <message>
        <source>Another zone feed is being fetched.</source>
        <translation>Інша стрічка зон уже завантажується.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no web address (http:// or https://).</source>
        <translation>«%1» — не вебадреса (http:// або https://).</translation>
    </message>
    <message>
        <source>There is no folder to keep the zone feed in (%1).</source>
        <translation>Немає теки, щоб зберегти стрічку зон (%1).</translation>
    </message>
    <message>
        <source>The zone feed is larger than %1 MiB; it was not kept.</source>
        <translation>Стрічка зон більша за %1 МіБ; її не збережено.</translation>
    </message>
    <message>
        <source>The zone feed&apos;s fetch was stopped (cancelled, or no answer for %1 s).</source>
        <translation>Завантаження стрічки зон зупинено (скасовано або немає відповіді %1 с).</translation>
    </message>
    <message>
        <source>The zone feed&apos;s server answered HTTP %1.</source>
        <translation>Сервер стрічки зон відповів HTTP %1.</translation>
    </message>
    <message>
        <source>The zone feed cannot be fetched: %1.</source>
        <translation>Стрічку зон не вдається завантажити: %1.</translation>
    </message>
    <message>
        <source>The zone feed&apos;s server sent nothing.</source>
        <translation>Сервер стрічки зон нічого не надіслав.</translation>
    </message>
    <message>
        <source>The zone feed cannot be kept in %1: %2.</source>
        <translation>Стрічку зон не вдається зберегти в %1: %2.</translation>
    </message>
</context>
<context>
    <name>sortie::airspace::ZoneSharing</name>
    <message>
        <source>Wait: the server has not answered the last change yet.</source>
        <translation>Зачекайте: сервер ще не відповів на останню зміну.</translation>
    </message>
    <message>
        <source>Only a zone drawn here can be sent to the server.</source>
        <translation>Надіслати на сервер можна лише зону, намальовану тут.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was changed on the server since you copied it (version %2, now %3). Remove your copy and edit the server&apos;s zone again.</source>
        <translation>Зону «%1» змінено на сервері після того, як ви її скопіювали (версія %2, тепер %3). Видаліть свою копію й відредагуйте зону сервера знову.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; is on the server; you changed it since sending, so your copy stays.</source>
        <translation>Зона «%1» є на сервері; ви змінили її після надсилання, тож ваша копія лишається.</translation>
    </message>
    <message>
        <source>Send zone &apos;%1&apos; to the server</source>
        <translation>Надіслати зону «%1» на сервер</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; is on the server.</source>
        <translation>Зона «%1» є на сервері.</translation>
    </message>
    <message>
        <source>Only the server&apos;s custom zones can be edited here; aerodrome zones are the server&apos;s own.</source>
        <translation>Тут можна редагувати лише власні зони сервера; зони аеродромів належать серверу.</translation>
    </message>
    <message>
        <source>Edit server zone &apos;%1&apos;</source>
        <translation>Редагувати зону сервера «%1»</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; is drawn here to edit; send it to store the change on the server.</source>
        <translation>Зону «%1» намальовано тут для редагування; надішліть її, щоб зберегти зміну на сервері.</translation>
    </message>
    <message>
        <source>Only the server&apos;s custom zones can be deleted here.</source>
        <translation>Тут можна видалити лише власні зони сервера.</translation>
    </message>
    <message>
        <source>Zone &apos;%1&apos; was deleted on the server.</source>
        <translation>Зону «%1» видалено на сервері.</translation>
    </message>
</context>
<context>
    <name>sortie::client::AutosaveRecovery</name>
    <message>
        <source>The autosaved edits in %1 cannot be read: %2</source>
        <translation>Не вдається прочитати автозбережені зміни в %1: %2</translation>
    </message>
    <message>
        <source>The autosaved edits in %1 cannot be read (%2). The file was kept as %3.</source>
        <translation>Не вдається прочитати автозбережені зміни в %1 (%2). Файл збережено як %3.</translation>
    </message>
    <message>
        <source>The autosaved edits in %1 cannot be read (%2).</source>
        <translation>Не вдається прочитати автозбережені зміни в %1 (%2).</translation>
    </message>
    <message>
        <source>Untitled route</source>
        <translation>Маршрут без назви</translation>
    </message>
    <message>
        <source>route %1, version %2</source>
        <translation>маршрут %1, версія %2</translation>
    </message>
    <message>
        <source>, on %1</source>
        <translation>, на %1</translation>
    </message>
    <message>
        <source> as %1</source>
        <translation> як %1</translation>
    </message>
    <message>
        <source>The route open now has unsaved edits, and restoring would replace it: save or undo them first.</source>
        <translation>Відкритий зараз маршрут має незбережені зміни, і відновлення замінить його: спершу збережіть або поверніть їх.</translation>
    </message>
    <message>
        <source>%1 as %2</source>
        <translation>%1 як %2</translation>
    </message>
    <message>
        <source>These edits belong to route %1 on %2, and saving them updates that route. Sign in to %2 to restore them: choose Later, sign in, and they are offered again.</source>
        <translation>Ці зміни належать маршруту %1 на %2, і їх збереження оновить той маршрут. Увійдіть на %2, щоб відновити їх: виберіть «Пізніше», увійдіть, і їх буде запропоновано знову.</translation>
    </message>
    <message>
        <source>These edits belong to route %1 on %2, but this session is signed in to %3 as %4. Sign out and sign in to %2 to restore them; until then they are kept and offered again at each start.</source>
        <translation>Ці зміни належать маршруту %1 на %2, але цей сеанс увійшов на %3 як %4. Вийдіть і увійдіть на %2, щоб відновити їх; доти вони зберігаються й пропонуються знову під час кожного запуску.</translation>
    </message>
    <message>
        <source>Restore autosaved edits</source>
        <translation>Відновити автозбережені зміни</translation>
    </message>
    <message>
        <source>The autosave %1 could not be moved aside.</source>
        <translation>Не вдалося перемістити автозбереження %1 убік.</translation>
    </message>
</context>
<context>
    <name>sortie::client::CommandPolicy</name>
    <message>
        <source>Manual</source>
        <translation>Ручний</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Утримання</translation>
    </message>
    <message>
        <source>Taking off</source>
        <translation>Зліт</translation>
    </message>
    <message>
        <source>Auto (fly the mission)</source>
        <translation>Авто (виконання місії)</translation>
    </message>
    <message>
        <source>Guided</source>
        <translation>Керований</translation>
    </message>
    <message>
        <source>Land</source>
        <translation>Посадка</translation>
    </message>
    <message>
        <source>Return home</source>
        <translation>Повернення додому</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Невідомий</translation>
    </message>
    <message>
        <source>the vehicle</source>
        <translation>апарат</translation>
    </message>
    <message>
        <source>Arm %1? Its motors may start.</source>
        <translation>Розблокувати %1? Його мотори можуть запуститися.</translation>
    </message>
    <message>
        <source>Disarm %1? It may be in the air, and would fall.</source>
        <translation>Заблокувати %1? Він може бути в повітрі й упаде.</translation>
    </message>
    <message>
        <source>Take off with %1 to %2 m above home?</source>
        <translation>Зліт %1 на висоту %2 m над точкою дому?</translation>
    </message>
    <message numerus="yes">
        <source>Start the mission on %1 (%n waypoint(s))?</source>
        <translation>
            <numerusform>Почати місію на %1 (%n точка)?</numerusform>
            <numerusform>Почати місію на %1 (%n точки)?</numerusform>
            <numerusform>Почати місію на %1 (%n точок)?</numerusform>
        </translation>
    </message>
    <message>
        <source>Start the mission on %1? Sortie has not seen its mission.</source>
        <translation>Почати місію на %1? Sortie не бачив його місії.</translation>
    </message>
    <message>
        <source>Arm</source>
        <translation>Увімкнути двигуни</translation>
    </message>
    <message>
        <source>Disarm</source>
        <translation>Вимкнути двигуни</translation>
    </message>
    <message>
        <source>Take off</source>
        <translation>Зліт</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Авто</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <source>%1 sent despite the checklist (the operator overrode it): %2</source>
        <translation>%1 надіслано попри контрольний список (оператор його обійшов): %2</translation>
    </message>
</context>
<context>
    <name>sortie::client::ConnectionController</name>
    <message>
        <source>connection lost; attempt %1 in %2 s</source>
        <translation>зв’язок втрачено; спроба %1 через %2 s</translation>
    </message>
    <message>
        <source>reconnected in a new session</source>
        <translation>перепідключено в новому сеансі</translation>
    </message>
    <message>
        <source>%1 at %2</source>
        <translation>%1 на %2</translation>
    </message>
    <message>
        <source>The server address is not usable: %1.</source>
        <translation>Адреса сервера непридатна: %1.</translation>
    </message>
    <message>
        <source>Enter a user name.</source>
        <translation>Введіть ім’я користувача.</translation>
    </message>
    <message>
        <source>%1. Check the server&apos;s address and this computer&apos;s network.</source>
        <translation>%1. Перевірте адресу сервера й мережу цього комп’ютера.</translation>
    </message>
    <message>
        <source>%1. Is the UgCS server running, and is the port right?</source>
        <translation>%1. Чи запущено сервер UgCS і чи правильний порт?</translation>
    </message>
    <message>
        <source>Wrong user name or password (%1).</source>
        <translation>Неправильне ім’я користувача або пароль (%1).</translation>
    </message>
    <message>
        <source>%1. This server cannot be used with Sortie.</source>
        <translation>%1. Цей сервер не можна використовувати із Sortie.</translation>
    </message>
    <message>
        <source>The server&apos;s licence allows no more connections (%1). Close another client or extend the licence.</source>
        <translation>Ліцензія сервера не дозволяє більше підключень (%1). Закрийте інший клієнт або розширте ліцензію.</translation>
    </message>
    <message>
        <source>The server did not answer in time (%1). It may be overloaded or not a UgCS server.</source>
        <translation>Сервер не відповів вчасно (%1). Можливо, він перевантажений або це не сервер UgCS.</translation>
    </message>
    <message>
        <source>The connection was closed (%1).</source>
        <translation>З’єднання закрито (%1).</translation>
    </message>
    <message>
        <source>The server answered something Sortie cannot use (%1).</source>
        <translation>Сервер відповів чимось, що Sortie не може використати (%1).</translation>
    </message>
    <message>
        <source>The server refused: %1</source>
        <translation>Сервер відмовив: %1</translation>
    </message>
    <message>
        <source>Disconnected</source>
        <translation>Від&apos;єднано</translation>
    </message>
    <message>
        <source>Connecting</source>
        <translation>З&apos;єднання</translation>
    </message>
    <message>
        <source>Authorizing</source>
        <translation>Авторизація</translation>
    </message>
    <message>
        <source>Logging in</source>
        <translation>Вхід</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Готово</translation>
    </message>
    <message>
        <source>Reconnecting</source>
        <translation>Повторне з&apos;єднання</translation>
    </message>
    <message>
        <source>%1 is not this computer, and this connection is not secured: the password for %2 would cross the network in clear, readable by anyone on the way, at every login and reconnect. Send it in clear to this server? (Choose Secure if the server is behind a TLS terminator.)</source>
        <translation>%1 — не цей комп’ютер, і це з’єднання не захищене: пароль для %2 йтиме мережею незашифрованим, доступним для читання будь-кому дорогою, під час кожного входу й перепідключення. Надіслати його незашифрованим на цей сервер? (Оберіть «Захищено», якщо сервер за TLS-термінатором.)</translation>
    </message>
    <message>
        <source>Not connected to %1: the password was not sent.</source>
        <translation>Не підключено до %1: пароль не надіслано.</translation>
    </message>
    <message>
        <source>First secure connection to %1: its certificate is now trusted for this server and remembered. Compare its SHA-256 fingerprint with the server&apos;s: %2</source>
        <translation>Перше захищене з’єднання з %1: його сертифікату тепер довіряють для цього сервера, і його збережено. Порівняйте його відбиток SHA-256 з відбитком сервера: %2</translation>
    </message>
    <message>
        <source>Secured by TLS: the certificate remembered for %1 (SHA-256 %2).</source>
        <translation>Захищено TLS: сертифікат, збережений для %1 (SHA-256 %2).</translation>
    </message>
    <message>
        <source>Secured by TLS: the certificate pinned for %1 (SHA-256 %2).</source>
        <translation>Захищено TLS: сертифікат, закріплений для %1 (SHA-256 %2).</translation>
    </message>
    <message>
        <source>Secured by TLS: a certificate this computer trusts (SHA-256 %1).</source>
        <translation>Захищено TLS: сертифікат, якому довіряє цей комп’ютер (SHA-256 %1).</translation>
    </message>
    <message>
        <source>%1. The password was not sent.</source>
        <translation>%1. Пароль не надіслано.</translation>
    </message>
</context>
<context>
    <name>sortie::client::FleetRoutes</name>
    <message>
        <source>Unnamed route</source>
        <translation>Маршрут без назви</translation>
    </message>
    <message>
        <source>planned</source>
        <translation>заплановано</translation>
    </message>
    <message>
        <source>uploaded %1</source>
        <translation>завантажено %1</translation>
    </message>
    <message>
        <source>paused: waypoint %1 of %2</source>
        <translation>пауза: точка %1 з %2</translation>
    </message>
    <message>
        <source>flying: waypoint %1 of %2</source>
        <translation>у польоті: точка %1 з %2</translation>
    </message>
    <message>
        <source>flown</source>
        <translation>виконано</translation>
    </message>
</context>
<context>
    <name>sortie::client::MissionController</name>
    <message>
        <source>Reading the server&apos;s routes</source>
        <translation>Читання маршрутів сервера</translation>
    </message>
    <message>
        <source>The server&apos;s routes could not be read: %1</source>
        <translation>Не вдалося прочитати маршрути сервера: %1</translation>
    </message>
    <message numerus="yes">
        <source>%1%n segment(s)</source>
        <translation>
            <numerusform>%1%n сегмент</numerusform>
            <numerusform>%1%n сегменти</numerusform>
            <numerusform>%1%n сегментів</numerusform>
        </translation>
    </message>
    <message>
        <source>Reading the server&apos;s vehicles</source>
        <translation>Читання апаратів сервера</translation>
    </message>
    <message>
        <source>Opening the route</source>
        <translation>Відкриття маршруту</translation>
    </message>
    <message>
        <source>The route could not be opened: %1</source>
        <translation>Не вдалося відкрити маршрут: %1</translation>
    </message>
    <message>
        <source>The route cannot be edited here: %1</source>
        <translation>Маршрут не можна редагувати тут: %1</translation>
    </message>
    <message>
        <source>Opened %1 (version %2).</source>
        <translation>Відкрито %1 (версія %2).</translation>
    </message>
    <message>
        <source>Not connected: your edits are kept; save again when the connection is back.</source>
        <translation>Немає підключення: ваші зміни збережено; збережіть знову, коли зв’язок відновиться.</translation>
    </message>
    <message>
        <source>Wait until %1 is done.</source>
        <translation>Зачекайте, доки завершиться: %1.</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>Не збережено: %1</translation>
    </message>
    <message>
        <source>Saving</source>
        <translation>Збереження</translation>
    </message>
    <message>
        <source>Locking the route</source>
        <translation>Блокування маршруту</translation>
    </message>
    <message>
        <source>Not saved: the route is locked (%1).</source>
        <translation>Не збережено: маршрут заблоковано (%1).</translation>
    </message>
    <message>
        <source>Reading the server&apos;s copy</source>
        <translation>Читання копії сервера</translation>
    </message>
    <message>
        <source>Someone else saved this route on the server (version %1) after you opened it (version %2).</source>
        <translation>Хтось інший зберіг цей маршрут на сервері (версія %1) після того, як ви його відкрили (версія %2).</translation>
    </message>
    <message>
        <source>Saved, but the server&apos;s answer cannot be read back: %1</source>
        <translation>Збережено, але не вдається прочитати відповідь сервера: %1</translation>
    </message>
    <message>
        <source>Saved %1 (version %2).</source>
        <translation>Збережено %1 (версія %2).</translation>
    </message>
    <message>
        <source>Take the server&apos;s version</source>
        <translation>Взяти версію сервера</translation>
    </message>
    <message>
        <source>This is the server&apos;s copy now. Undo brings your edits back.</source>
        <translation>Тепер це копія сервера. «Вернути» поверне ваші зміни.</translation>
    </message>
    <message>
        <source>This route was deleted on the server. Your copy stays open.</source>
        <translation>Цей маршрут видалено на сервері. Ваша копія залишається відкритою.</translation>
    </message>
    <message>
        <source>Updated from the server (version %1).</source>
        <translation>Оновлено із сервера (версія %1).</translation>
    </message>
    <message>
        <source>Someone else saved this route on the server (version %1) while you were editing it.</source>
        <translation>Хтось інший зберіг цей маршрут на сервері (версія %1), поки ви його редагували.</translation>
    </message>
    <message>
        <source>The new route</source>
        <translation>Новий маршрут</translation>
    </message>
    <message>
        <source>&quot;%1&quot;</source>
        <translation>«%1»</translation>
    </message>
    <message>
        <source>%1 has unsaved edits. Opening it again reads the server&apos;s copy. Save your edits first?</source>
        <translation>%1 має незбережені зміни. Повторне відкриття прочитає копію сервера. Спершу зберегти зміни?</translation>
    </message>
    <message>
        <source>%1 has unsaved edits. Save them before opening &quot;%2&quot;?</source>
        <translation>%1 має незбережені зміни. Зберегти їх перед відкриттям «%2»?</translation>
    </message>
    <message>
        <source>If you discard them, Undo brings them back.</source>
        <translation>Якщо їх відкинути, «Скасувати дію» поверне їх.</translation>
    </message>
    <message>
        <source>the new route</source>
        <translation>нового маршруту</translation>
    </message>
    <message>
        <source>Open %1</source>
        <translation>Відкрити %1</translation>
    </message>
    <message>
        <source>Undo brings back your unsaved edits of %1.</source>
        <translation>«Скасувати дію» поверне ваші незбережені зміни %1.</translation>
    </message>
    <message>
        <source>Not saved: another route was opened meanwhile.</source>
        <translation>Не збережено: тим часом було відкрито інший маршрут.</translation>
    </message>
    <message>
        <source>Edits made while saving</source>
        <translation>Зміни під час збереження</translation>
    </message>
    <message>
        <source>The edits you made while it was saving are kept, not saved yet.</source>
        <translation>Зміни, зроблені під час збереження, збережено в документі, але ще не на сервері.</translation>
    </message>
    <message>
        <source>Update from the server (version %1)</source>
        <translation>Оновлення із сервера (версія %1)</translation>
    </message>
</context>
<context>
    <name>sortie::client::MissionUploader</name>
    <message>
        <source>Checking the route</source>
        <translation>Перевірка маршруту</translation>
    </message>
    <message>
        <source>Waiting for your answer</source>
        <translation>Очікування вашої відповіді</translation>
    </message>
    <message>
        <source>Processing for %1</source>
        <translation>Обробка для %1</translation>
    </message>
    <message>
        <source>Taking control of %1</source>
        <translation>Отримання керування %1</translation>
    </message>
    <message>
        <source>Uploading to %1</source>
        <translation>Завантаження в %1</translation>
    </message>
    <message>
        <source>Releasing %1</source>
        <translation>Звільнення керування %1</translation>
    </message>
    <message>
        <source>Reading the mission back from %1</source>
        <translation>Зчитування місії з %1</translation>
    </message>
    <message>
        <source>upload &quot;%1&quot;</source>
        <translation>завантаження «%1»</translation>
    </message>
    <message>
        <source>route</source>
        <translation>маршрут</translation>
    </message>
    <message>
        <source>Upload to %1 failed: the vehicle is gone (its connection was closed).</source>
        <translation>Не вдалося завантажити в %1: апарат зник (його з’єднання закрито).</translation>
    </message>
    <message>
        <source>the vehicle is gone</source>
        <translation>апарат зник</translation>
    </message>
    <message>
        <source>Not uploaded: %1</source>
        <translation>Не завантажено: %1</translation>
    </message>
    <message>
        <source>Too late to cancel: the mission is being sent to %1.</source>
        <translation>Запізно скасовувати: місія вже надсилається в %1.</translation>
    </message>
    <message>
        <source>Upload to %1 cancelled; nothing was sent.</source>
        <translation>Завантаження в %1 скасовано; нічого не надіслано.</translation>
    </message>
    <message>
        <source>Upload to %1 failed: the vehicle has no link.</source>
        <translation>Не вдалося завантажити в %1: апарат не має зв’язку.</translation>
    </message>
    <message>
        <source>no link</source>
        <translation>немає зв’язку</translation>
    </message>
    <message>
        <source>Not uploaded to %1: %2</source>
        <translation>Не завантажено в %1: %2</translation>
    </message>
    <message>
        <source>the route&apos;s fence is not sent: %1 keeps no fence (HCI)</source>
        <translation>геозону маршруту не надіслано: %1 не зберігає геозону (HCI)</translation>
    </message>
    <message>
        <source>Upload to %1 failed: %2</source>
        <translation>Не вдалося завантажити в %1: %2</translation>
    </message>
    <message>
        <source>Uploaded to %1, but it could not be read back: %2</source>
        <translation>Завантажено в %1, але не вдалося зчитати назад: %2</translation>
    </message>
    <message>
        <source>Uploaded to %1, but it holds something else: %2</source>
        <translation>Завантажено в %1, але на борту інше: %2</translation>
    </message>
    <message numerus="yes">
        <source>Uploaded to %1: %n waypoint(s).</source>
        <translation>
            <numerusform>Завантажено в %1: %n точка.</numerusform>
            <numerusform>Завантажено в %1: %n точки.</numerusform>
            <numerusform>Завантажено в %1: %n точок.</numerusform>
        </translation>
    </message>
    <message>
        <source>Note: %1</source>
        <translation>Примітка: %1</translation>
    </message>
</context>
<context>
    <name>sortie::client::RouteAutosave</name>
    <message>
        <source>No free autosave slot in %1: edits are not autosaved.</source>
        <translation>Немає вільного слота автозбереження в %1: зміни не автозберігаються.</translation>
    </message>
</context>
<context>
    <name>sortie::client::RouteDocument</name>
    <message>
        <source>Import failed: %1</source>
        <translation>Імпорт не вдався: %1</translation>
    </message>
    <message>
        <source>Import failed: %1 holds no route.</source>
        <translation>Імпорт не вдався: %1 не містить маршруту.</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Імпорт %1</translation>
    </message>
    <message numerus="yes">
        <source>Imported %n segment(s) from %1.</source>
        <translation>
            <numerusform>Імпортовано %n сегмент із %1.</numerusform>
            <numerusform>Імпортовано %n сегменти з %1.</numerusform>
            <numerusform>Імпортовано %n сегментів з %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>The file holds %1 routes; this is the first (&quot;%2&quot;).</source>
        <translation>Файл містить маршрутів: %1; це перший («%2»).</translation>
    </message>
    <message>
        <source>Export failed: %1</source>
        <translation>Експорт не вдався: %1</translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation>Експортовано в %1.</translation>
    </message>
    <message>
        <source>Not representable there: %1</source>
        <translation>Не можна там відобразити: %1</translation>
    </message>
</context>
<context>
    <name>sortie::client::RoutePreparation</name>
    <message>
        <source>Choose the vehicle to %1 for.</source>
        <translation>Виберіть апарат, щоб %1.</translation>
    </message>
    <message>
        <source>process the route</source>
        <translation>обробити маршрут</translation>
    </message>
    <message>
        <source>%1 has no link.</source>
        <translation>%1 не має зв’язку.</translation>
    </message>
    <message>
        <source>Processing for %1…</source>
        <translation>Обробка для %1…</translation>
    </message>
    <message>
        <source>Not processed for %1: %2</source>
        <translation>Не оброблено для %1: %2</translation>
    </message>
    <message numerus="yes">
        <source>Processed for %1: %n waypoint(s) to fly.</source>
        <translation>
            <numerusform>Оброблено для %1: до польоту %n точка.</numerusform>
            <numerusform>Оброблено для %1: до польоту %n точки.</numerusform>
            <numerusform>Оброблено для %1: до польоту %n точок.</numerusform>
        </translation>
    </message>
    <message>
        <source>upload</source>
        <translation>завантажити</translation>
    </message>
    <message>
        <source>An upload is waiting for your answer.</source>
        <translation>Завантаження очікує вашої відповіді.</translation>
    </message>
    <message>
        <source>Wait until %1 is done.</source>
        <translation>Зачекайте, доки завершиться: %1.</translation>
    </message>
</context>
<context>
    <name>sortie::client::VehicleFleet</name>
    <message>
        <source>%1: %2 done.</source>
        <translation>%1: %2 — виконано.</translation>
    </message>
    <message>
        <source>%1: %2 failed: %3</source>
        <translation>%1: %2 — помилка: %3</translation>
    </message>
    <message>
        <source>The server&apos;s vehicles could not be read: %1</source>
        <translation>Не вдалося прочитати апарати сервера: %1</translation>
    </message>
    <message>
        <source>Not a VCI address: %1</source>
        <translation>Це не адреса VCI: %1</translation>
    </message>
    <message>
        <source>go to %1, %2 at %3 m</source>
        <translation>летіти до %1, %2 на %3 m</translation>
    </message>
    <message>
        <source>%1: flying to the clicked point.</source>
        <translation>%1: летить до вказаної точки.</translation>
    </message>
    <message>
        <source>%1: go-to failed: %2</source>
        <translation>%1: переліт не вдався: %2</translation>
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
            <numerusform>%1 (%n точка)</numerusform>
            <numerusform>%1 (%n точки)</numerusform>
            <numerusform>%1 (%n точок)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Arm %n vehicle(s): %1? Their motors may start.</source>
        <translation>
            <numerusform>Розблокувати %n апарат: %1? Їхні мотори можуть запуститися.</numerusform>
            <numerusform>Розблокувати %n апарати: %1? Їхні мотори можуть запуститися.</numerusform>
            <numerusform>Розблокувати %n апаратів: %1? Їхні мотори можуть запуститися.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Disarm %n vehicle(s): %1? One in the air would fall.</source>
        <translation>
            <numerusform>Заблокувати %n апарат: %1? Той, що в повітрі, впаде.</numerusform>
            <numerusform>Заблокувати %n апарати: %1? Той, що в повітрі, впаде.</numerusform>
            <numerusform>Заблокувати %n апаратів: %1? Той, що в повітрі, впаде.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Take off with %n vehicle(s) to their altitudes above home: %1?</source>
        <translation>
            <numerusform>Зліт %n апарата на їхні висоти над точкою дому: %1?</numerusform>
            <numerusform>Зліт %n апаратів на їхні висоти над точкою дому: %1?</numerusform>
            <numerusform>Зліт %n апаратів на їхні висоти над точкою дому: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Start or resume the mission on %n vehicle(s): %1?</source>
        <translation>
            <numerusform>Почати або продовжити місію на %n апараті: %1?</numerusform>
            <numerusform>Почати або продовжити місію на %n апаратах: %1?</numerusform>
            <numerusform>Почати або продовжити місію на %n апаратах: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Pause %n vehicle(s) where they are: %1?</source>
        <translation>
            <numerusform>Призупинити %n апарат на місці: %1?</numerusform>
            <numerusform>Призупинити %n апарати на місці: %1?</numerusform>
            <numerusform>Призупинити %n апаратів на місці: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Land %n vehicle(s) where they are: %1?</source>
        <translation>
            <numerusform>Посадити %n апарат на місці: %1?</numerusform>
            <numerusform>Посадити %n апарати на місці: %1?</numerusform>
            <numerusform>Посадити %n апаратів на місці: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Send %n vehicle(s) home: %1?</source>
        <translation>
            <numerusform>Відправити %n апарат додому: %1?</numerusform>
            <numerusform>Відправити %n апарати додому: %1?</numerusform>
            <numerusform>Відправити %n апаратів додому: %1?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Switch %n vehicle(s) to %2: %1?</source>
        <translation>
            <numerusform>Перемкнути %n апарат у %2: %1?</numerusform>
            <numerusform>Перемкнути %n апарати в %2: %1?</numerusform>
            <numerusform>Перемкнути %n апаратів у %2: %1?</numerusform>
        </translation>
    </message>
    <message>
        <source>not sent</source>
        <translation>не надіслано</translation>
    </message>
    <message>
        <source>%1 waiting</source>
        <translation>%1 очікує</translation>
    </message>
    <message>
        <source>%1 done</source>
        <translation>%1 виконано</translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation>%1 помилка: %2</translation>
    </message>
    <message numerus="yes">
        <source>%1: %2 of %n vehicle(s) answered — %3.</source>
        <translation>
            <numerusform>%1: відповіли %2 з %n апарата — %3.</numerusform>
            <numerusform>%1: відповіли %2 з %n апаратів — %3.</numerusform>
            <numerusform>%1: відповіли %2 з %n апаратів — %3.</numerusform>
        </translation>
    </message>
    <message>
        <source>Held back by their checklist, not sent: %1.</source>
        <translation>Затримано їхнім контрольним списком, не надіслано: %1.</translation>
    </message>
    <message>
        <source>held back by its checklist (%1)</source>
        <translation>затримано його контрольним списком (%1)</translation>
    </message>
</context>
<context>
    <name>sortie::coverage::PhotoSurvey</name>
    <message>
        <source>Choose the vehicle that took the photos.</source>
        <translation>Оберіть апарат, що зробив знімки.</translation>
    </message>
    <message>
        <source>choose the camera that took them</source>
        <translation>оберіть камеру, що їх зробила</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>не виміряно</translation>
    </message>
    <message>
        <source>Open the flight&apos;s log first.</source>
        <translation>Спершу відкрийте журнал польоту.</translation>
    </message>
    <message>
        <source>Choose the folder of the flight&apos;s photos.</source>
        <translation>Оберіть теку зі знімками польоту.</translation>
    </message>
    <message>
        <source>No photo is placed: nothing to write.</source>
        <translation>Жоден знімок не розміщено: нічого записувати.</translation>
    </message>
    <message>
        <source>%1 is the photos&apos; own folder: the copies go elsewhere, the originals are never changed.</source>
        <translation>%1 — власна тека знімків: копії йдуть деінде, оригінали ніколи не змінюються.</translation>
    </message>
    <message>
        <source>%1: the folder cannot be made.</source>
        <translation>%1: теку не вдається створити.</translation>
    </message>
    <message numerus="yes">
        <source>%n geotagged copies, geo.txt and geotags.csv written to %1.</source>
        <translation>
            <numerusform>%n копію з геопозицією, geo.txt і geotags.csv записано в %1.</numerusform>
            <numerusform>%n копії з геопозицією, geo.txt і geotags.csv записано в %1.</numerusform>
            <numerusform>%n копій з геопозицією, geo.txt і geotags.csv записано в %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 not written: %2.</source>
        <translation>%1 не записано: %2.</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n photos placed on %2&apos;s track (camera clock %3 s).</source>
        <translation>
            <numerusform>%1 з %n знімка розміщено на треку %2 (годинник камери %3 с).</numerusform>
            <numerusform>%1 з %n знімків розміщено на треку %2 (годинник камери %3 с).</numerusform>
            <numerusform>%1 з %n знімків розміщено на треку %2 (годинник камери %3 с).</numerusform>
        </translation>
    </message>
    <message>
        <source>Coverage not judged: %1.</source>
        <translation>Покриття не оцінено: %1.</translation>
    </message>
    <message numerus="yes">
        <source>%1 % of %2 m² seen by at least %3 images; forward overlap %4, side %5; %6 per pixel; %n hole(s).</source>
        <translation>
            <numerusform>%1 % з %2 м² бачать щонайменше %3 знімків; поздовжнє перекриття %4, поперечне %5; %6 на піксель; %n прогалина.</numerusform>
            <numerusform>%1 % з %2 м² бачать щонайменше %3 знімків; поздовжнє перекриття %4, поперечне %5; %6 на піксель; %n прогалини.</numerusform>
            <numerusform>%1 % з %2 м² бачать щонайменше %3 знімків; поздовжнє перекриття %4, поперечне %5; %6 на піксель; %n прогалин.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 m² at %2, %3</source>
        <translation>%1 м² у %2, %3</translation>
    </message>
    <message>
        <source>No hole could be planned as an area scan: %1</source>
        <translation>Жодну прогалину не вдалося спланувати як зйомку площі: %1</translation>
    </message>
    <message>
        <source>Re-fly the gaps</source>
        <translation>Перелетіти прогалини</translation>
    </message>
    <message numerus="yes">
        <source>&quot;Re-fly the gaps&quot; is open in the mission editor: %n area scan(s) at %1 m, %2/%3 % overlap.</source>
        <translation>
            <numerusform>«Перелетіти прогалини» відкрито в редакторі місій: %n зйомка площі на %1 м, перекриття %2/%3 %.</numerusform>
            <numerusform>«Перелетіти прогалини» відкрито в редакторі місій: %n зйомки площі на %1 м, перекриття %2/%3 %.</numerusform>
            <numerusform>«Перелетіти прогалини» відкрито в редакторі місій: %n зйомок площі на %1 м, перекриття %2/%3 %.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n photos placed where %2 took them, paired with its photo events (camera clock %3 s off).</source>
        <translation>
            <numerusform>%1 з %n фото розміщено там, де %2 його зробив, за його подіями фото (годинник камери зсунуто на %3 с).</numerusform>
            <numerusform>%1 з %n фото розміщено там, де %2 їх зробив, за його подіями фото (годинник камери зсунуто на %3 с).</numerusform>
            <numerusform>%1 з %n фото розміщено там, де %2 їх зробив, за його подіями фото (годинник камери зсунуто на %3 с).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n photo(s) the vehicle took are not in the folder.</source>
        <translation>
            <numerusform>%n фото, зроблене апаратом, відсутнє в теці.</numerusform>
            <numerusform>%n фото, зроблені апаратом, відсутні в теці.</numerusform>
            <numerusform>%n фото, зроблених апаратом, немає в теці.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sortie::deconfliction::FleetConflictRule</name>
    <message>
        <source>%1, flying &quot;%2&quot; (its leg %3)</source>
        <translation>%1, виконує «%2» (його ділянка %3)</translation>
    </message>
    <message>
        <source>%1&apos;s uploaded &quot;%2&quot; (its leg %3) if it starts now</source>
        <translation>«%2», завантажений у %1 (його ділянка %3), якщо він стартує зараз</translation>
    </message>
    <message>
        <source>Leg %1 comes within %2 m across and %3 m in height of %4, %5 after the start%6.</source>
        <translation>Ділянка %1 наближається до %4 на %2 m по горизонталі та %3 m по висоті через %5 після старту%6.</translation>
    </message>
    <message>
        <source> (heights in different frames: judged across only)</source>
        <translation> (висоти в різних системах відліку: оцінено лише по горизонталі)</translation>
    </message>
</context>
<context>
    <name>sortie::deconfliction::ProximityMonitor</name>
    <message>
        <source>now</source>
        <translation>зараз</translation>
    </message>
    <message>
        <source>in %1 s</source>
        <translation>через %1 s</translation>
    </message>
    <message>
        <source>%1 and traffic %2: closest %3, %4 across and %5 in height</source>
        <translation>%1 і борт %2: найближче %3, %4 по горизонталі та %5 по висоті</translation>
    </message>
    <message>
        <source>%1 and %2: closest %3, %4 across and %5 in height</source>
        <translation>%1 і %2: найближче %3, %4 по горизонталі та %5 по висоті</translation>
    </message>
</context>
<context>
    <name>sortie::endurance::EnduranceAdvisory</name>
    <message>
        <source>No vehicle chosen</source>
        <translation>Апарат не вибрано</translation>
    </message>
    <message>
        <source>No energy profile: choose the vehicle&apos;s profile file on the mission page</source>
        <translation>Немає енергетичного профілю: виберіть файл профілю апарата на сторінці місії</translation>
    </message>
    <message>
        <source>The vehicle reports no remaining battery</source>
        <translation>Апарат не повідомляє залишок батареї</translation>
    </message>
    <message>
        <source>The vehicle reports no home</source>
        <translation>Апарат не повідомляє точку дому</translation>
    </message>
    <message>
        <source>The vehicle reports no position</source>
        <translation>Апарат не повідомляє позицію</translation>
    </message>
    <message>
        <source>No mission on board</source>
        <translation>Немає місії на борту</translation>
    </message>
    <message>
        <source>The vehicle cannot make headway home against the wind</source>
        <translation>Апарат не може просуватися додому проти вітру</translation>
    </message>
    <message>
        <source>Battery at end of route: %1 · home needs %2</source>
        <translation>Батарея в кінці маршруту: %1 · додому потрібно %2</translation>
    </message>
    <message>
        <source>Battery: time to come home — no headway home against the wind</source>
        <translation>Батарея: час повертатися — проти вітру додому не просунутися</translation>
    </message>
    <message>
        <source>Battery: time to come home — %1 left, home needs %2: the %3 reserve is being used</source>
        <translation>Батарея: час повертатися — лишилося %1, додому потрібно %2: резерв %3 витрачається</translation>
    </message>
    <message>
        <source>Battery: time to come home — %1 left, home needs %2 and the reserve %3: %4 to spare</source>
        <translation>Батарея: час повертатися — лишилося %1, додому потрібно %2 і резерв %3: запас %4</translation>
    </message>
    <message>
        <source>Return %1 home now? %2</source>
        <translation>Повернути %1 додому зараз? %2</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ComparisonController</name>
    <message>
        <source>Open a flight log first.</source>
        <translation>Спочатку відкрийте журнал польоту.</translation>
    </message>
    <message>
        <source>%1 holds no route.</source>
        <translation>%1 не містить маршруту.</translation>
    </message>
    <message>
        <source>Choose the vehicle to compare on the map or in the list.</source>
        <translation>Виберіть апарат для порівняння на карті або в списку.</translation>
    </message>
    <message>
        <source>%1 on &quot;%2&quot;: %3 of %4 waypoints reached; cross-track max %5 m, mean %6 m; altitude max %7 m</source>
        <translation>%1 на «%2»: досягнуто %3 з %4 точок; бічне відхилення макс %5 m, середнє %6 m; висота макс %7 m</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::FlightLogWriter</name>
    <message>
        <source>%1: the log cannot use a write-ahead journal</source>
        <translation>%1: журнал не може використовувати режим WAL (попередній запис)</translation>
    </message>
    <message>
        <source>Recording could not continue in %1: %2</source>
        <translation>Запис не вдалося продовжити в %1: %2</translation>
    </message>
    <message>
        <source>%1 is being written by another process</source>
        <translation>%1 записує інший процес</translation>
    </message>
    <message>
        <source>Recording to %1 failed: %2. What is recorded meanwhile is kept and written once it can be.</source>
        <translation>Запис у %1 не вдався: %2. Записане тим часом зберігається і буде записане, щойно це стане можливим.</translation>
    </message>
    <message numerus="yes">
        <source>Recording to %1 resumed; %n value(s) recorded while it failed could not be kept.</source>
        <translation>
            <numerusform>Запис у %1 відновлено; %n значення, записане під час збою, не вдалося зберегти.</numerusform>
            <numerusform>Запис у %1 відновлено; %n значення, записані під час збою, не вдалося зберегти.</numerusform>
            <numerusform>Запис у %1 відновлено; %n значень, записаних під час збою, не вдалося зберегти.</numerusform>
        </translation>
    </message>
    <message>
        <source>no row for vehicle %1: %2</source>
        <translation>немає рядка для апарата %1: %2</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::FlightRecorder</name>
    <message>
        <source>The flight log %1 cannot be written: %2</source>
        <translation>Не вдається записати журнал польоту %1: %2</translation>
    </message>
    <message>
        <source>Recording started</source>
        <translation>Запис розпочато</translation>
    </message>
    <message>
        <source>Recording stopped</source>
        <translation>Запис зупинено</translation>
    </message>
    <message>
        <source>Route of 1 waypoint</source>
        <translation>Маршрут з 1 точки</translation>
    </message>
    <message>
        <source>Route of %1 waypoints</source>
        <translation>Маршрут, точок: %1</translation>
    </message>
    <message>
        <source>Armed</source>
        <translation>Розблоковано</translation>
    </message>
    <message>
        <source>Disarmed</source>
        <translation>Заблоковано</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::RecordingSettings</name>
    <message>
        <source>In force: %1; %2.</source>
        <translation>Діє: %1; %2.</translation>
    </message>
    <message>
        <source>a log up to %1 MB</source>
        <translation>журнал до %1 МБ</translation>
    </message>
    <message>
        <source>logs of any size</source>
        <translation>журнали будь-якого розміру</translation>
    </message>
    <message>
        <source>the folder up to %1 MB</source>
        <translation>тека до %1 МБ</translation>
    </message>
    <message>
        <source>the folder without limit</source>
        <translation>тека без обмеження</translation>
    </message>
    <message>
        <source>A log&apos;s size must be between 1 and %1 MB, or 0 for no limit.</source>
        <translation>Розмір журналу має бути від 1 до %1 МБ або 0 без обмеження.</translation>
    </message>
    <message>
        <source>The folder&apos;s size must be between 1 and %1 MB, or 0 for no limit.</source>
        <translation>Розмір теки має бути від 1 до %1 МБ або 0 без обмеження.</translation>
    </message>
    <message>
        <source>The folder must hold at least one whole log: make its limit at least a log&apos;s size (%1 MB).</source>
        <translation>Тека має вміщувати щонайменше один цілий журнал: задайте її обмеження не менше за розмір журналу (%1 МБ).</translation>
    </message>
    <message>
        <source>%1 in 1 log</source>
        <translation>%1 в 1 журналі</translation>
    </message>
    <message>
        <source>%1 in %2 logs</source>
        <translation>%1, журналів: %2</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ReplayController</name>
    <message>
        <source>%1 of 1 vehicle</source>
        <translation>%1, 1 апарат</translation>
    </message>
    <message>
        <source>%1 of %2 vehicles</source>
        <translation>%1, апаратів: %2</translation>
    </message>
    <message>
        <source>No log is open.</source>
        <translation>Журнал не відкрито.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an export format (gpx, kml or csv).</source>
        <translation>«%1» не є форматом експорту (gpx, kml або csv).</translation>
    </message>
    <message>
        <source>%1 could not be written: %2</source>
        <translation>Не вдалося записати %1: %2</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ServerHistory</name>
    <message>
        <source>not connected to a server</source>
        <translation>немає підключення до сервера</translation>
    </message>
    <message>
        <source>The server&apos;s history could not be read: %1</source>
        <translation>Не вдалося прочитати історію сервера: %1</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ServerHistoryRequest</name>
    <message>
        <source>The server lists no vehicles: connect to a server first.</source>
        <translation>Сервер не має апаратів: спершу підключіться до сервера.</translation>
    </message>
    <message>
        <source>Choose a vehicle.</source>
        <translation>Виберіть апарат.</translation>
    </message>
    <message>
        <source>The start &quot;%1&quot; is not a time like %2 (UTC).</source>
        <translation>Початок «%1» не є часом у форматі %2 (UTC).</translation>
    </message>
    <message>
        <source>The end &quot;%1&quot; is not a time like %2 (UTC).</source>
        <translation>Кінець «%1» не є часом у форматі %2 (UTC).</translation>
    </message>
    <message>
        <source>The start must be before the end.</source>
        <translation>Початок має бути раніше за кінець.</translation>
    </message>
    <message>
        <source>The start is in the future.</source>
        <translation>Початок — у майбутньому.</translation>
    </message>
    <message>
        <source>At most 24 hours at a time.</source>
        <translation>Не більше 24 годин за раз.</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Скасовано.</translation>
    </message>
    <message>
        <source>The server has no telemetry of %1 from %2 to %3 UTC.</source>
        <translation>Сервер не має телеметрії %1 з %2 до %3 UTC.</translation>
    </message>
    <message>
        <source>There is no replay to show it in.</source>
        <translation>Немає відтворення, у якому це показати.</translation>
    </message>
</context>
<context>
    <name>sortie::flightlog::ServerRecording</name>
    <message>
        <source>logged in to %1 as %2; recording to %3</source>
        <translation>вхід на %1 як %2; запис у %3</translation>
    </message>
    <message>
        <source>server: %1</source>
        <translation>сервер: %1</translation>
    </message>
    <message>
        <source>1 vehicle</source>
        <translation>1 апарат</translation>
    </message>
    <message>
        <source>%1 vehicles</source>
        <translation>апаратів: %1</translation>
    </message>
    <message>
        <source>log closed: %1</source>
        <translation>журнал закрито: %1</translation>
    </message>
    <message>
        <source>a pinned certificate needs a tls://host:port server and a SHA-256 fingerprint</source>
        <translation>закріпленому сертифікату потрібні сервер tls://host:port і відбиток SHA-256</translation>
    </message>
    <message>
        <source>%1 is not this computer and the connection is not secured: the password would cross the network in clear. Record over TLS (--server tls://%1), or pass --allow-cleartext to send it in clear.</source>
        <translation>%1 — не цей комп’ютер, і з’єднання не захищене: пароль пройшов би мережею відкритим текстом. Записуйте через TLS (--server tls://%1) або вкажіть --allow-cleartext, щоб надіслати його відкритим текстом.</translation>
    </message>
</context>
<context>
    <name>sortie::gamepad::GamepadCommands</name>
    <message>
        <source>Gamepads off</source>
        <translation>Геймпади вимкнено</translation>
    </message>
    <message>
        <source>Gamepads unavailable: %1</source>
        <translation>Геймпади недоступні: %1</translation>
    </message>
    <message>
        <source>No gamepad attached</source>
        <translation>Геймпад не під’єднано</translation>
    </message>
</context>
<context>
    <name>sortie::gamepad::GamepadManager</name>
    <message>
        <source>Another gamepad manager already owns SDL in this program.</source>
        <translation>Інший диспетчер геймпадів уже володіє SDL у цій програмі.</translation>
    </message>
    <message>
        <source>Gamepads are not available: %1</source>
        <translation>Геймпади недоступні: %1</translation>
    </message>
</context>
<context>
    <name>sortie::maptiles::OfflineMaps</name>
    <message>
        <source>No route is open.</source>
        <translation>Жоден маршрут не відкрито.</translation>
    </message>
    <message>
        <source>The open route has no waypoints to take the area from.</source>
        <translation>Відкритий маршрут не має точок, за якими визначити район.</translation>
    </message>
    <message>
        <source>The route is a single point: give a margin around it.</source>
        <translation>Маршрут — це одна точка: задайте відступ навколо неї.</translation>
    </message>
    <message numerus="yes">
        <source>The open route (%n point(s)) and %1 m around it</source>
        <translation>
            <numerusform>Відкритий маршрут (%n точка) і %1 m навколо нього</numerusform>
            <numerusform>Відкритий маршрут (%n точки) і %1 m навколо нього</numerusform>
            <numerusform>Відкритий маршрут (%n точок) і %1 m навколо нього</numerusform>
        </translation>
    </message>
    <message>
        <source>The map&apos;s view is not an area (%1 to %2).</source>
        <translation>Видима область карти не є районом (від %1 до %2).</translation>
    </message>
    <message>
        <source>The map&apos;s view</source>
        <translation>Видима область карти</translation>
    </message>
    <message>
        <source>The lowest zoom is above the highest.</source>
        <translation>Найменший масштаб більший за найбільший.</translation>
    </message>
    <message>
        <source>Choose an area.</source>
        <translation>Виберіть район.</translation>
    </message>
    <message>
        <source>%1 tiles, about %2</source>
        <translation>Тайлів: %1, приблизно %2</translation>
    </message>
    <message>
        <source> (at this pack&apos;s mean of %1 a tile)</source>
        <translation> (за середнім для цього пакета %1 на тайл)</translation>
    </message>
    <message>
        <source> (assuming %1 a tile)</source>
        <translation> (за припущення %1 на тайл)</translation>
    </message>
    <message>
        <source>: more than the limit of %1 tiles, choose a smaller area or fewer zoom levels</source>
        <translation>: більше за ліміт у %1 тайлів, виберіть менший район або менше рівнів масштабу</translation>
    </message>
    <message>
        <source>Choose a web tile server in Map source first: %1</source>
        <translation>Спочатку виберіть веб-сервер тайлів у «Джерело карти»: %1</translation>
    </message>
    <message>
        <source>%1 of %2 tiles</source>
        <translation>%1 з %2 тайлів</translation>
    </message>
    <message>
        <source> · %1 already in the pack</source>
        <translation> · уже в пакеті: %1</translation>
    </message>
    <message>
        <source> · %1 not stored</source>
        <translation> · не збережено: %1</translation>
    </message>
    <message>
        <source> · paused</source>
        <translation> · пауза</translation>
    </message>
    <message>
        <source> · done</source>
        <translation> · готово</translation>
    </message>
    <message>
        <source> · stopped</source>
        <translation> · зупинено</translation>
    </message>
    <message>
        <source> · failed</source>
        <translation> · помилка</translation>
    </message>
    <message>
        <source>The drawn area cannot be used: %1</source>
        <translation>Намальовану область не можна використати: %1</translation>
    </message>
    <message numerus="yes">
        <source>A drawn area (%n corner(s))</source>
        <translation>
            <numerusform>Намальована область (%n кут)</numerusform>
            <numerusform>Намальована область (%n кути)</numerusform>
            <numerusform>Намальована область (%n кутів)</numerusform>
        </translation>
    </message>
    <message>
        <source>The drawn rectangle is not an area (%1 to %2).</source>
        <translation>Намальований прямокутник не є областю (від %1 до %2).</translation>
    </message>
    <message>
        <source>A drawn rectangle</source>
        <translation>Намальований прямокутник</translation>
    </message>
</context>
<context>
    <name>sortie::maptiles::TilePrefetch</name>
    <message>
        <source>No area is chosen.</source>
        <translation>Район не вибрано.</translation>
    </message>
    <message>
        <source>The zoom range %1 to %2 is not within 0 to %3.</source>
        <translation>Діапазон масштабу від %1 до %2 не в межах від 0 до %3.</translation>
    </message>
    <message>
        <source>The area needs %1 tiles, more than the limit of %2: choose a smaller area or fewer zoom levels.</source>
        <translation>Для району потрібно тайлів: %1, більше за ліміт %2: виберіть менший район або менше рівнів масштабу.</translation>
    </message>
    <message>
        <source>Tiles from %1, taken offline by %2</source>
        <translation>Тайли з %1, збережені для офлайну програмою %2</translation>
    </message>
    <message>
        <source>not an image (%1, %2 bytes)</source>
        <translation>не зображення (%1, %2 байт)</translation>
    </message>
    <message>
        <source>no answer within %1 s</source>
        <translation>немає відповіді протягом %1 s</translation>
    </message>
    <message>
        <source>%1 (after %2 attempts)</source>
        <translation>%1 (спроб: %2)</translation>
    </message>
</context>
<context>
    <name>sortie::mission::RouteEditor</name>
    <message>
        <source>Nothing is selected.</source>
        <translation>Нічого не вибрано.</translation>
    </message>
    <message>
        <source>That is not a valid position.</source>
        <translation>Це некоректна позиція.</translation>
    </message>
    <message>
        <source>There is no row %1 to insert at.</source>
        <translation>Немає рядка %1 для вставлення.</translation>
    </message>
    <message>
        <source>Add waypoint %1</source>
        <translation>Додати точку %1</translation>
    </message>
    <message>
        <source>A move needs one position per waypoint.</source>
        <translation>Для переміщення потрібна одна позиція на кожну точку.</translation>
    </message>
    <message>
        <source>There is no row %1.</source>
        <translation>Немає рядка %1.</translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>Пересунути %1</translation>
    </message>
    <message numerus="yes">
        <source>Move %n segment(s)</source>
        <translation>
            <numerusform>Пересунути %n сегмент</numerusform>
            <numerusform>Пересунути %n сегменти</numerusform>
            <numerusform>Пересунути %n сегментів</numerusform>
        </translation>
    </message>
    <message>
        <source>Row %1 is not a waypoint.</source>
        <translation>Рядок %1 не є точкою маршруту.</translation>
    </message>
    <message>
        <source>The altitude needs a number.</source>
        <translation>Для висоти потрібне число.</translation>
    </message>
    <message>
        <source>Set altitude to %1 m</source>
        <translation>Задати висоту %1 m</translation>
    </message>
    <message>
        <source>Set altitude type to %1</source>
        <translation>Задати тип висоти %1</translation>
    </message>
    <message>
        <source>Row %1 keeps its height %2: set it as %2, or change its altitude type first.</source>
        <translation>Рядок %1 зберігає свою висоту %2: задайте її як %2 або спершу змініть тип висоти.</translation>
    </message>
    <message>
        <source>Waypoint %1 is planned %2 and there is no terrain data under it: a height %3 cannot be converted.</source>
        <translation>Точку %1 заплановано в %2, і під нею немає даних рельєфу: висоту %3 не можна перерахувати.</translation>
    </message>
    <message>
        <source>Set altitude to %1 m %2</source>
        <translation>Задати висоту %1 m %2</translation>
    </message>
    <message>
        <source>Set turn type to %1</source>
        <translation>Задати тип повороту %1</translation>
    </message>
    <message>
        <source>No selected segment has a parameter &quot;%1&quot;.</source>
        <translation>Жоден вибраний сегмент не має параметра «%1».</translation>
    </message>
    <message>
        <source>Set %1 to %2</source>
        <translation>Задати %1: %2</translation>
    </message>
    <message>
        <source>There is no action &quot;%1&quot;.</source>
        <translation>Немає дії «%1».</translation>
    </message>
    <message>
        <source>Add action: %1</source>
        <translation>Додати дію: %1</translation>
    </message>
    <message>
        <source>Remove action</source>
        <translation>Видалити дію</translation>
    </message>
    <message>
        <source>There is no action &quot;%1&quot; with these values.</source>
        <translation>Немає дії «%1» з такими значеннями.</translation>
    </message>
    <message>
        <source>Edit action: %1</source>
        <translation>Змінити дію: %1</translation>
    </message>
    <message>
        <source>Clear actions</source>
        <translation>Очистити дії</translation>
    </message>
    <message>
        <source>An area scan needs at least three corners that enclose an area.</source>
        <translation>Скануванню площі потрібні щонайменше три кути, що охоплюють площу.</translation>
    </message>
    <message>
        <source>Add area scan</source>
        <translation>Додати сканування площі</translation>
    </message>
    <message>
        <source>Segment %1 has no point %2.</source>
        <translation>Сегмент %1 не має точки %2.</translation>
    </message>
    <message>
        <source>Move point %1 of segment %2</source>
        <translation>Пересунути точку %1 сегмента %2</translation>
    </message>
    <message>
        <source>Segment %1 has no edge there.</source>
        <translation>Сегмент %1 не має там ребра.</translation>
    </message>
    <message>
        <source>Add a point to segment %1</source>
        <translation>Додати точку до сегмента %1</translation>
    </message>
    <message numerus="yes">
        <source>This figure keeps at least %n point(s).</source>
        <translation>
            <numerusform>У цієї фігури лишається щонайменше %n точка.</numerusform>
            <numerusform>У цієї фігури лишаються щонайменше %n точки.</numerusform>
            <numerusform>У цієї фігури лишається щонайменше %n точок.</numerusform>
        </translation>
    </message>
    <message>
        <source>Remove point %1 of segment %2</source>
        <translation>Видалити точку %1 сегмента %2</translation>
    </message>
    <message>
        <source>A radius is above 0 m.</source>
        <translation>Радіус має бути більше 0 m.</translation>
    </message>
    <message>
        <source>Segment %1 is no circle.</source>
        <translation>Сегмент %1 не є колом.</translation>
    </message>
    <message>
        <source>Set the radius of segment %1 to %2 m</source>
        <translation>Задати радіус сегмента %1: %2 m</translation>
    </message>
    <message>
        <source>A point segment needs one valid position.</source>
        <translation>Точковому сегменту потрібна одна коректна позиція.</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>Додати %1</translation>
    </message>
    <message>
        <source>Sortie has no description of the algorithm %1.</source>
        <translation>Sortie не має опису алгоритму %1.</translation>
    </message>
    <message numerus="yes">
        <source>%1 needs at least %n point(s)%2.</source>
        <translation>
            <numerusform>Для %1 потрібна щонайменше %n точка%2.</numerusform>
            <numerusform>Для %1 потрібні щонайменше %n точки%2.</numerusform>
            <numerusform>Для %1 потрібно щонайменше %n точок%2.</numerusform>
        </translation>
    </message>
    <message>
        <source> enclosing an area</source>
        <translation>, що охоплюють площу</translation>
    </message>
    <message>
        <source>A route has no setting &quot;%1&quot;.</source>
        <translation>Маршрут не має налаштування «%1».</translation>
    </message>
    <message>
        <source>%1 needs a number.</source>
        <translation>Для %1 потрібне число.</translation>
    </message>
    <message>
        <source>Set route %1</source>
        <translation>Задати для маршруту: %1</translation>
    </message>
    <message>
        <source>Plan the start for %1</source>
        <translation>Запланувати старт на %1</translation>
    </message>
    <message>
        <source>Start now</source>
        <translation>Почати зараз</translation>
    </message>
    <message>
        <source>An authorisation needs the zone&apos;s identifier.</source>
        <translation>Дозвіл потребує ідентифікатора зони.</translation>
    </message>
    <message>
        <source>Remove the authorisation for %1</source>
        <translation>Прибрати дозвіл для %1</translation>
    </message>
    <message>
        <source>Record authorisation %1 for %2</source>
        <translation>Записати дозвіл %1 для %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no start time: type it as %2, e.g. %3.</source>
        <translation>«%1» — не час старту: введіть як %2, напр. %3.</translation>
    </message>
</context>
<context>
    <name>sortie::mission::SegmentEditorModel</name>
    <message>
        <source>A parameter Sortie has no description of: kept and sent as typed.</source>
        <translation>Параметр, якого Sortie не знає: зберігається й надсилається як введено.</translation>
    </message>
    <message>
        <source>%1 (vehicle profile)</source>
        <translation>%1 (профіль апарата)</translation>
    </message>
    <message>
        <source>%1 needs a number, not &quot;%2&quot;.</source>
        <translation>Для %1 потрібне число, а не «%2».</translation>
    </message>
    <message>
        <source>%1 m high · %2 cm/px · footprint %3 × %4 m · passes %5 m apart · photo every %6 m · %7 photos</source>
        <translation>%1 м висоти · %2 см/пкс · кадр %3 × %4 м · проходи через %5 м · фото кожні %6 м · %7 фото</translation>
    </message>
</context>
<context>
    <name>sortie::mission::SegmentPreview</name>
    <message>
        <source>This segment cannot be planned.</source>
        <translation>Цей сегмент не можна спланувати.</translation>
    </message>
</context>
<context>
    <name>sortie::mission::WaypointActionsModel</name>
    <message>
        <source>Actions at waypoint %1</source>
        <translation>Дії в точці %1</translation>
    </message>
    <message>
        <source>Actions at %1 waypoints</source>
        <translation>Дії в точках (%1)</translation>
    </message>
    <message>
        <source>There is no action &quot;%1&quot;.</source>
        <translation>Немає дії «%1».</translation>
    </message>
    <message>
        <source>This action has no field &quot;%1&quot;.</source>
        <translation>Ця дія не має поля «%1».</translation>
    </message>
    <message>
        <source>Choose an action to add.</source>
        <translation>Виберіть дію, щоб додати.</translation>
    </message>
</context>
<context>
    <name>sortie::preflight::PreflightChecklists</name>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>Не вдається прочитати %1: %2</translation>
    </message>
</context>
<context>
    <name>sortie::preflight::VehicleChecklist</name>
    <message>
        <source>2D fix</source>
        <translation>2D-фіксація</translation>
    </message>
    <message>
        <source>3D fix</source>
        <translation>3D-фіксація</translation>
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
        <source>no fix</source>
        <translation>немає фіксації</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Link to the vehicle</source>
        <translation>Зв’язок з апаратом</translation>
    </message>
    <message>
        <source>GPS fix</source>
        <translation>GPS-фіксація</translation>
    </message>
    <message>
        <source>Satellites</source>
        <translation>Супутники</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Батарея</translation>
    </message>
    <message>
        <source>Home position</source>
        <translation>Домашня точка</translation>
    </message>
    <message>
        <source>Route on board</source>
        <translation>Маршрут на борту</translation>
    </message>
    <message>
        <source>Route check</source>
        <translation>Перевірка маршруту</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Камера</translation>
    </message>
    <message>
        <source>ticked</source>
        <translation>позначено</translation>
    </message>
    <message>
        <source>not reported over this vehicle&apos;s link</source>
        <translation>не передається зв’язком цього апарата</translation>
    </message>
    <message>
        <source>to tick</source>
        <translation>треба позначити</translation>
    </message>
    <message>
        <source>Sortie has uploaded no route to it</source>
        <translation>Sortie не завантажував йому маршрут</translation>
    </message>
    <message>
        <source>its route is not the one open</source>
        <translation>його маршрут не той, що відкритий</translation>
    </message>
    <message>
        <source>not known: no fresh telemetry</source>
        <translation>невідомо: немає свіжої телеметрії</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>підключено</translation>
    </message>
    <message>
        <source>no fresh telemetry</source>
        <translation>немає свіжої телеметрії</translation>
    </message>
    <message>
        <source>%1 (%2 needed)</source>
        <translation>%1 (потрібно %2)</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>%1 % (%2 % needed)</source>
        <translation>%1 % (потрібно %2 %)</translation>
    </message>
    <message>
        <source>set</source>
        <translation>задано</translation>
    </message>
    <message>
        <source>not set</source>
        <translation>не задано</translation>
    </message>
    <message>
        <source>the planned route</source>
        <translation>запланований маршрут</translation>
    </message>
    <message>
        <source>differs from the planned route: upload it</source>
        <translation>відрізняється від запланованого маршруту: завантажте його</translation>
    </message>
    <message>
        <source>no errors</source>
        <translation>без помилок</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n помилка</numerusform>
            <numerusform>%n помилки</numerusform>
            <numerusform>%n помилок</numerusform>
        </translation>
    </message>
    <message>
        <source>stream reported</source>
        <translation>потік повідомлено</translation>
    </message>
    <message>
        <source>no stream reported</source>
        <translation>потік не повідомлено</translation>
    </message>
</context>
<context>
    <name>sortie::resume::MissionResume</name>
    <message>
        <source>The route</source>
        <translation>Маршрут</translation>
    </message>
    <message numerus="yes">
        <source>%1 stopped flying to waypoint %2 of %3, after %n photo(s).</source>
        <translation>
            <numerusform>%1 зупинився дорогою до точки %2 з %3 після %n фото.</numerusform>
            <numerusform>%1 зупинився дорогою до точки %2 з %3 після %n фото.</numerusform>
            <numerusform>%1 зупинився дорогою до точки %2 з %3 після %n фото.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 stopped flying to waypoint %2 of %3.</source>
        <translation>%1 зупинився дорогою до точки %2 з %3.</translation>
    </message>
    <message>
        <source>There is nothing to resume: no vehicle stands with a route flown part of the way.</source>
        <translation>Нічого продовжувати: жоден апарат не стоїть з частково пройденим маршрутом.</translation>
    </message>
    <message>
        <source>The vehicle took no photo on this route.</source>
        <translation>Апарат не зробив жодного фото на цьому маршруті.</translation>
    </message>
    <message>
        <source>The vehicle reached no waypoint of this route.</source>
        <translation>Апарат не досяг жодної точки цього маршруту.</translation>
    </message>
    <message>
        <source>Resume the mission</source>
        <translation>Продовжити місію</translation>
    </message>
</context>
<context>
    <name>sortie::secrets::PasswordVault</name>
    <message>
        <source>the keyring did not answer</source>
        <translation>сховище паролів не відповіло</translation>
    </message>
</context>
<context>
    <name>sortie::traffic::SbsFeed</name>
    <message>
        <source>no answer within %1 s</source>
        <translation>немає відповіді протягом %1 s</translation>
    </message>
    <message>
        <source>the receiver closed the connection</source>
        <translation>приймач закрив з’єднання</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not host:port</source>
        <translation>«%1» не у форматі host:port</translation>
    </message>
    <message>
        <source>receiver off</source>
        <translation>приймач вимкнено</translation>
    </message>
    <message>
        <source>receiver: %1</source>
        <translation>приймач: %1</translation>
    </message>
    <message>
        <source>receiver: connecting to %1</source>
        <translation>приймач: підключення до %1</translation>
    </message>
    <message>
        <source>receiver %1</source>
        <translation>приймач %1</translation>
    </message>
    <message>
        <source>receiver: %1; again in %2 s</source>
        <translation>приймач: %1; повтор через %2 s</translation>
    </message>
</context>
<context>
    <name>sortie::ui::AppSettings</name>
    <message>
        <source>The password an earlier version kept in the settings file is now in the keyring.</source>
        <translation>Пароль, який попередня версія зберігала у файлі налаштувань, тепер у сховищі паролів.</translation>
    </message>
    <message>
        <source>The password an earlier version kept in the settings file was erased from it; the keyring refused it (%1), so it is not remembered.</source>
        <translation>Пароль, який попередня версія зберігала у файлі налаштувань, стерто з нього; сховище паролів його не прийняло (%1), тож його не запам’ятано.</translation>
    </message>
    <message>
        <source>The keyring refused the password (%1): it is not remembered.</source>
        <translation>Сховище паролів не прийняло пароль (%1): його не запам’ятано.</translation>
    </message>
    <message>
        <source>The remembered password could not be read from the keyring (%1).</source>
        <translation>Не вдалося прочитати запам’ятований пароль зі сховища паролів (%1).</translation>
    </message>
    <message>
        <source>The password could not be removed from the keyring (%1).</source>
        <translation>Не вдалося видалити пароль зі сховища паролів (%1).</translation>
    </message>
    <message>
        <source>No keyring is reachable, so the password cannot be remembered (%1).</source>
        <translation>Сховище паролів недоступне, тому пароль не можна запам’ятати (%1).</translation>
    </message>
    <message>
        <source>The password an earlier version kept in the settings file was erased from it.</source>
        <translation>Пароль, який попередня версія зберігала у файлі налаштувань, стерто з нього.</translation>
    </message>
</context>
<context>
    <name>sortie::ui::AttitudeIndicator</name>
    <message>
        <source>no attitude</source>
        <translation>немає орієнтації</translation>
    </message>
</context>
<context>
    <name>sortie::ui::ConflictLayer</name>
    <message>
        <source>%1 at %2:%3, %4 m / %5 m</source>
        <translation>%1 о %2:%3, %4 m / %5 m</translation>
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
        <translation>відключено</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>підключення</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>підключено</translation>
    </message>
    <message>
        <source>link lost</source>
        <translation>зв’язок втрачено</translation>
    </message>
</context>
<context>
    <name>sortie::ui::ElevationProfileView</name>
    <message>
        <source>Leg %1 · %2 · ground %3 · altitude %4 · clearance %5</source>
        <translation>Ділянка %1 · %2 · рельєф %3 · висота %4 · запас висоти %5</translation>
    </message>
    <message>
        <source>no data</source>
        <translation>немає даних</translation>
    </message>
    <message>
        <source>Add two waypoints to see the terrain profile</source>
        <translation>Додайте дві точки, щоб побачити профіль рельєфу</translation>
    </message>
    <message>
        <source>No terrain source</source>
        <translation>Немає джерела рельєфу</translation>
    </message>
    <message>
        <source>Ground: %1</source>
        <translation>Рельєф: %1</translation>
    </message>
    <message>
        <source>lowest clearance %1</source>
        <translation>найменший запас висоти %1</translation>
    </message>
    <message>
        <source>clearance unknown</source>
        <translation>запас висоти невідомий</translation>
    </message>
    <message>
        <source>no return</source>
        <translation>точка неповернення</translation>
    </message>
    <message>
        <source>battery change</source>
        <translation>заміна батареї</translation>
    </message>
</context>
<context>
    <name>sortie::ui::EnduranceLayer</name>
    <message>
        <source>Battery change</source>
        <translation>Заміна батареї</translation>
    </message>
    <message>
        <source>Battery change needed</source>
        <translation>Потрібна заміна батареї</translation>
    </message>
    <message>
        <source>No return</source>
        <translation>Точка неповернення</translation>
    </message>
</context>
<context>
    <name>sortie::ui::FlightStatus</name>
    <message>
        <source>mission complete</source>
        <translation>місію виконано</translation>
    </message>
    <message>
        <source>waypoint %1 of %2</source>
        <translation>точка %1 з %2</translation>
    </message>
    <message>
        <source>1 waypoint on board</source>
        <translation>1 точка на борту</translation>
    </message>
    <message>
        <source>%1 waypoints on board</source>
        <translation>Точок на борту: %1</translation>
    </message>
    <message>
        <source>no mission on board</source>
        <translation>немає місії на борту</translation>
    </message>
</context>
<context>
    <name>sortie::ui::GlanceStatus</name>
    <message>
        <source>No server</source>
        <translation>Немає сервера</translation>
    </message>
    <message>
        <source>No vehicle</source>
        <translation>Немає апарата</translation>
    </message>
    <message>
        <source>GPS —</source>
        <translation>GPS —</translation>
    </message>
    <message>
        <source>No fix</source>
        <translation>Немає фіксації</translation>
    </message>
    <message>
        <source>2D fix</source>
        <translation>2D-фіксація</translation>
    </message>
    <message>
        <source>3D fix</source>
        <translation>3D-фіксація</translation>
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
        <translation>%1, %2 суп.</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>%1 V</source>
        <translation>%1 В</translation>
    </message>
    <message>
        <source>Battery —</source>
        <translation>Акумулятор —</translation>
    </message>
    <message>
        <source>Link lost</source>
        <translation>Зв&apos;язок втрачено</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Гц</translation>
    </message>
    <message>
        <source>Link —</source>
        <translation>Зв&apos;язок —</translation>
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
        <translation>Файл MBTiles не задано.</translation>
    </message>
    <message>
        <source>The MBTiles file has no tile %1.</source>
        <translation>Файл MBTiles не має тайла %1.</translation>
    </message>
    <message>
        <source>Tile %1 in the MBTiles file is not a raster image.</source>
        <translation>Тайл %1 у файлі MBTiles не є растровим зображенням.</translation>
    </message>
</context>
<context>
    <name>sortie::ui::OfflineTileSource</name>
    <message>
        <source>Offline base map</source>
        <translation>Офлайн-базова карта</translation>
    </message>
    <message>
        <source>Land outlines: Natural Earth</source>
        <translation>Контури суходолу: Natural Earth</translation>
    </message>
    <message>
        <source>The built-in land outlines could not be read: %1</source>
        <translation>Не вдалося прочитати вбудовані контури суходолу: %1</translation>
    </message>
</context>
<context>
    <name>sortie::ui::PhotoLayer</name>
    <message>
        <source>Hole %1 m²</source>
        <translation>Прогалина %1 м²</translation>
    </message>
</context>
<context>
    <name>sortie::ui::RasterFileCheck</name>
    <message numerus="yes">
        <source>%n file(s) left out, the others are used:</source>
        <translation>
            <numerusform>%n файл пропущено, інші використовуються:</numerusform>
            <numerusform>%n файли пропущено, інші використовуються:</numerusform>
            <numerusform>%n файлів пропущено, інші використовуються:</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>and %n more (in the log)</source>
        <translation>
            <numerusform>і ще %n (у журналі)</numerusform>
            <numerusform>і ще %n (у журналі)</numerusform>
            <numerusform>і ще %n (у журналі)</numerusform>
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
        <translation>зараз</translation>
    </message>
    <message>
        <source>No data yet</source>
        <translation>Даних ще немає</translation>
    </message>
    <message>
        <source>Choose a vehicle</source>
        <translation>Виберіть апарат</translation>
    </message>
</context>
<context>
    <name>sortie::ui::TerrainProfileModel</name>
    <message>
        <source>no terrain source</source>
        <translation>немає джерела рельєфу</translation>
    </message>
    <message>
        <source>no terrain data (tried: %1)</source>
        <translation>немає даних рельєфу (спробувано: %1)</translation>
    </message>
    <message>
        <source> · loading…</source>
        <translation> · завантаження…</translation>
    </message>
    <message>
        <source>under this waypoint</source>
        <translation>під цією точкою</translation>
    </message>
    <message>
        <source>under this segment&apos;s points</source>
        <translation>під точками цього сегмента</translation>
    </message>
    <message>
        <source>Asking for the ground %1…</source>
        <translation>Запит рельєфу %1…</translation>
    </message>
    <message>
        <source>No terrain data %1 (tried: %2)</source>
        <translation>Немає даних рельєфу %1 (спробувано: %2)</translation>
    </message>
    <message>
        <source>Ground %1, metres above sea level (EGM96), from %2</source>
        <translation>Рельєф %1, метри над рівнем моря (EGM96), джерело: %2</translation>
    </message>
    <message>
        <source>; some points have no data (tried: %1)</source>
        <translation>; для деяких точок немає даних (спробувано: %1)</translation>
    </message>
</context>
<context>
    <name>sortie::ui::Theme</name>
    <message>
        <source>System colours</source>
        <translation>Кольори системи</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Світлі</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Темні</translation>
    </message>
    <message>
        <source>Sunlight (high contrast)</source>
        <translation>Сонячне світло (висока контрастність)</translation>
    </message>
</context>
<context>
    <name>sortie::ui::TileManager</name>
    <message>
        <source>Offline base map</source>
        <translation>Офлайн-базова карта</translation>
    </message>
    <message>
        <source>%1 — offline base map shown</source>
        <translation>%1 — показано офлайн-базову карту</translation>
    </message>
    <message numerus="yes">
        <source>%1: loading %n tile(s)</source>
        <translation>
            <numerusform>%1: завантаження %n тайла</numerusform>
            <numerusform>%1: завантаження %n тайлів</numerusform>
            <numerusform>%1: завантаження %n тайлів</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %n tile(s) missing — %2</source>
        <translation>
            <numerusform>%1: бракує %n тайла — %2</numerusform>
            <numerusform>%1: бракує %n тайлів — %2</numerusform>
            <numerusform>%1: бракує %n тайлів — %2</numerusform>
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
        <translation> набирає висоту</translation>
    </message>
    <message>
        <source> descending</source>
        <translation> знижується</translation>
    </message>
</context>
<context>
    <name>sortie::ui::Translations</name>
    <message>
        <source>System language</source>
        <translation>Системна мова</translation>
    </message>
</context>
<context>
    <name>sortie::ui::VideoItem</name>
    <message>
        <source>No video for this vehicle</source>
        <translation>Немає відео для цього апарата</translation>
    </message>
    <message>
        <source>hardware decoding (%1)</source>
        <translation>апаратне декодування (%1)</translation>
    </message>
    <message>
        <source>software decoding (%1)</source>
        <translation>програмне декодування (%1)</translation>
    </message>
</context>
<context>
    <name>sortie::ui::XyzTileSource</name>
    <message>
        <source>Web tiles</source>
        <translation>Веб-тайли</translation>
    </message>
    <message>
        <source>Tile %1 is not an image.</source>
        <translation>Тайл %1 не є зображенням.</translation>
    </message>
    <message>
        <source>Tile %1 is neither in the offline pack nor in the cache (cache only: the network is not used).</source>
        <translation>Тайла %1 немає ні в офлайн-пакеті, ні в кеші (лише кеш: мережа не використовується).</translation>
    </message>
    <message>
        <source>Tile %1 is not in the cache and the tile server is unreachable.</source>
        <translation>Тайла %1 немає в кеші, а сервер тайлів недоступний.</translation>
    </message>
    <message>
        <source>No tile file %1.</source>
        <translation>Немає файлу тайла %1.</translation>
    </message>
    <message>
        <source>The tile server answered HTTP %1 for tile %2.</source>
        <translation>Сервер тайлів відповів HTTP %1 для тайла %2.</translation>
    </message>
    <message>
        <source>Tile server unreachable (%1).</source>
        <translation>Сервер тайлів недоступний (%1).</translation>
    </message>
    <message>
        <source>Tile %1 is %2.</source>
        <translation>Плитка %1: %2.</translation>
    </message>
</context>
<context>
    <name>sortie::ui::ZoneLayer</name>
    <message>
        <source>drawn on the map</source>
        <translation>намальовано на карті</translation>
    </message>
    <message>
        <source>%1 (%2 zone)
Source: %3%4
Floor %5, ceiling %6</source>
        <translation>%1 (зона: %2)
Джерело: %3%4
Нижня межа %5, верхня межа %6</translation>
    </message>
    <message>
        <source>
Not checked: %1</source>
        <translation>
Не перевіряється: %1</translation>
    </message>
    <message>
        <source>
Switched off: not checked</source>
        <translation>
Вимкнено: не перевіряється</translation>
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
Причина: %1</translation>
    </message>
    <message>
        <source>
When: %1</source>
        <translation>
Коли: %1</translation>
    </message>
    <message>
        <source>
Not in force during the planned flight</source>
        <translation>
Не діє під час запланованого польоту</translation>
    </message>
    <message>
        <source>
Authority: %1</source>
        <translation>
Орган: %1</translation>
    </message>
</context>
<context>
    <name>sortie::vehicle::CommandLog</name>
    <message>
        <source>sent</source>
        <translation>надіслано</translation>
    </message>
    <message>
        <source>done</source>
        <translation>виконано</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>помилка</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>скасовано</translation>
    </message>
    <message>
        <source>alert</source>
        <translation>тривога</translation>
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
        <translation>Бракує %1 з GStreamer: встановіть %2</translation>
    </message>
    <message>
        <source>No %1 decoder: install %2</source>
        <translation>Немає декодера %1: встановіть %2</translation>
    </message>
    <message>
        <source>The video pipeline could not be built: %1</source>
        <translation>Не вдалося побудувати відеоконвеєр: %1</translation>
    </message>
    <message>
        <source>No %1: install %2</source>
        <translation>Немає %1: встановіть %2</translation>
    </message>
    <message>
        <source>A GStreamer plugin is missing: %1</source>
        <translation>Бракує плагіна GStreamer: %1</translation>
    </message>
    <message>
        <source>the stream ended</source>
        <translation>потік завершився</translation>
    </message>
    <message>
        <source>no frame for %1 s</source>
        <translation>немає кадру %1 с</translation>
    </message>
    <message>
        <source>no frame since the last attempt</source>
        <translation>немає кадру від останньої спроби</translation>
    </message>
    <message>
        <source>nothing received yet</source>
        <translation>ще нічого не отримано</translation>
    </message>
    <message>
        <source>No video URL</source>
        <translation>Немає URL відео</translation>
    </message>
    <message>
        <source>Video stopped</source>
        <translation>Відео зупинено</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>Підключення до %1…</translation>
    </message>
    <message>
        <source>Connecting to %1… (%2)</source>
        <translation>Підключення до %1… (%2)</translation>
    </message>
    <message>
        <source>%1, %2×%3, %4 decoding (%5)</source>
        <translation>%1, %2×%3, декодування: %4 (%5)</translation>
    </message>
    <message>
        <source>hardware</source>
        <translation>апаратне</translation>
    </message>
    <message>
        <source>software</source>
        <translation>програмне</translation>
    </message>
    <message>
        <source>No video since %1 (%2); reconnecting</source>
        <translation>Немає відео з %1 (%2); перепідключення</translation>
    </message>
</context>
<context>
    <name>sortie::video::VideoRuntime</name>
    <message>
        <source>GStreamer did not start: %1</source>
        <translation>GStreamer не запустився: %1</translation>
    </message>
</context>
</TS>
