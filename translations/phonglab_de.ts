<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de" sourcelanguage="en">
<context>
    <name>ObjectChoice</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>check: %1</source>
        <translation>Prüfung: %1</translation>
    </message>
    <message>
        <source>%1 against exact Phong: %2</source>
        <translation>%1 verglichen mit exaktem Phong: %2</translation>
    </message>
    <message>
        <source>analytic (exact)</source>
        <translation>analytisch (exakt)</translation>
    </message>
    <message>
        <source>from file</source>
        <translation>aus der Datei</translation>
    </message>
    <message>
        <source>, crease %1°</source>
        <translation>, Knickwinkel %1°</translation>
    </message>
    <message>
        <source>computed (%1)</source>
        <translation>berechnet (%1)</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>geschlossen</translation>
    </message>
    <message>
        <source>open (back faces drawn)</source>
        <translation>offen (Rückseiten werden gezeichnet)</translation>
    </message>
    <message>
        <source>%1 %: %2 of %3 triangles</source>
        <translation>%1 %: %2 von %3 Dreiecken</translation>
    </message>
    <message>
        <source>The file&apos;s normals; computed angle-weighted when it has none</source>
        <translation>Die Normalen der Datei; winkelgewichtet berechnet, wenn sie keine hat</translation>
    </message>
    <message>
        <source>Each face&apos;s own normal at all its corners (faceted)</source>
        <translation>Die eigene Normale jeder Fläche an all ihren Ecken (facettiert)</translation>
    </message>
    <message>
        <source>Unweighted mean of the normals of the faces around a vertex</source>
        <translation>Ungewichteter Mittelwert der Normalen der Flächen um einen Vertex</translation>
    </message>
    <message>
        <source>Face normals weighted by face area</source>
        <translation>Flächennormalen, gewichtet nach Flächeninhalt</translation>
    </message>
    <message>
        <source>Face normals weighted by the face&apos;s angle at the vertex</source>
        <translation>Flächennormalen, gewichtet nach dem Winkel der Fläche am Vertex</translation>
    </message>
    <message>
        <source>Faces meeting at a sharper angle than this do not share normals</source>
        <translation>Flächen, die in einem schärferen Winkel als diesem aufeinandertreffen, teilen sich keine Normalen</translation>
    </message>
    <message>
        <source>%1 meshes</source>
        <translation>%1 Meshes</translation>
    </message>
    <message>
        <source>%1 (%2 normals)</source>
        <translation>%1 (Normalen: %2)</translation>
    </message>
    <message>
        <source>%1 at %2 detail</source>
        <translation>%1, Detailstufe %2</translation>
    </message>
    <message>
        <source>levels of detail</source>
        <translation>Detailstufen</translation>
    </message>
    <message>
        <source>full detail</source>
        <translation>volle Detailstufe</translation>
    </message>
    <message>
        <source>Vertex</source>
        <translation>Vertex</translation>
    </message>
    <message>
        <source>Fragment</source>
        <translation>Fragment</translation>
    </message>
    <message>
        <source>(not editable here)</source>
        <translation>(hier nicht bearbeitbar)</translation>
    </message>
    <message>
        <source>%1 %2: not editable here</source>
        <translation>%1 %2: hier nicht bearbeitbar</translation>
    </message>
    <message>
        <source>%1 %2: set on the program as you edit; kept across recompiles</source>
        <translation>%1 %2: wird beim Bearbeiten im Programm gesetzt; bleibt beim erneuten Kompilieren erhalten</translation>
    </message>
    <message>
        <source>%1: level %2 of %3, %4 triangles</source>
        <translation>%1: Stufe %2 von %3, %4 Dreiecke</translation>
    </message>
    <message numerus="yes">
        <source>, %n light(s) left out</source>
        <translation>
            <numerusform>, %n Lichtquelle ausgelassen</numerusform>
            <numerusform>, %n Lichtquellen ausgelassen</numerusform>
        </translation>
    </message>
    <message>
        <source>No file to open.</source>
        <translation>Keine Datei zum Öffnen.</translation>
    </message>
    <message>
        <source>%1: PhongLab cannot open this kind of file. It opens scenes (.json) and meshes (.%2).</source>
        <translation>%1: PhongLab kann diese Art von Datei nicht öffnen. Es öffnet Szenen (.json) und Meshes (.%2).</translation>
    </message>
    <message>
        <source>%1: a scene file opens on its own. Open one scene, or any number of meshes.</source>
        <translation>%1: Eine Szenendatei wird nur für sich allein geöffnet. Bitte eine Szene oder beliebig viele Meshes öffnen.</translation>
    </message>
    <message>
        <source>PhongLab scenes (*.json);;All files (*)</source>
        <translation>PhongLab-Szenen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Meshes (%1);;All files (*)</source>
        <translation>Meshes (%1);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>cannot open the default scene: %1</source>
        <translation>die Standardszene kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>PhongLab</source>
        <translation>PhongLab</translation>
    </message>
    <message>
        <source>Cannot open</source>
        <translation>Öffnen nicht möglich</translation>
    </message>
    <message>
        <source>%1

%2

Showing the default scene instead.</source>
        <translation>%1

%2

Stattdessen wird die Standardszene angezeigt.</translation>
    </message>
    <message>
        <source>%1

Showing the default scene instead.</source>
        <translation>%1

Stattdessen wird die Standardszene angezeigt.</translation>
    </message>
    <message>
        <source>the check failed: %1</source>
        <translation>die Prüfung ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>cannot connect to the X display &apos;%1&apos; (DISPLAY)</source>
        <translation>keine Verbindung zum X-Display &apos;%1&apos; (DISPLAY)</translation>
    </message>
    <message>
        <source>phonglab: the editor window needs a display (X11 or Wayland), and DISPLAY is not set.
The commands render, check, grade, mesh-info and bench run without one (phonglab --help).</source>
        <translation>phonglab: Das Editorfenster braucht ein Display (X11 oder Wayland), und DISPLAY ist nicht gesetzt.
Die Befehle render, check, grade, mesh-info und bench laufen ohne (phonglab --help).</translation>
    </message>
    <message>
        <source>%1: choose what it means in Uniforms</source>
        <translation>%1: Unter „Uniform-Variablen“ auswählen, was sie bedeutet</translation>
    </message>
    <message>
        <source>check: %1 — %2</source>
        <translation>Prüfung: %1 — %2</translation>
    </message>
    <message>
        <source>nothing to compare: no surface away from silhouettes in this view</source>
        <translation>nichts zu vergleichen: keine Oberfläche abseits der Silhouetten in dieser Ansicht</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>The check could not run: %1</source>
        <translation>Die Prüfung konnte nicht laufen: %1</translation>
    </message>
    <message>
        <source>choose what %1 means in Uniforms</source>
        <translation>unter „Uniform-Variablen“ auswählen, was %1 bedeutet</translation>
    </message>
    <message>
        <source>no verdict: choose what %1 %2 in Uniforms</source>
        <translation>kein Urteil: unter „Uniform-Variablen“ auswählen, was %1 %2</translation>
    </message>
    <message>
        <source>means</source>
        <translation>bedeutet</translation>
    </message>
    <message>
        <source>mean</source>
        <translation>bedeuten</translation>
    </message>
    <message>
        <source>no verdict: %1</source>
        <translation>kein Urteil: %1</translation>
    </message>
    <message>
        <source>see the check&apos;s panel</source>
        <translation>siehe das Prüfungsfenster</translation>
    </message>
    <message>
        <source>last good program: %1</source>
        <translation>letztes fehlerfreies Programm: %1</translation>
    </message>
</context>
<context>
    <name>SceneCommands</name>
    <message>
        <source>Edit light %1</source>
        <translation>Licht %1 bearbeiten</translation>
    </message>
    <message>
        <source>Switch on light %1</source>
        <translation>Licht %1 einschalten</translation>
    </message>
    <message>
        <source>Switch off light %1</source>
        <translation>Licht %1 ausschalten</translation>
    </message>
    <message>
        <source>Rename light %1</source>
        <translation>Licht %1 umbenennen</translation>
    </message>
    <message>
        <source>Edit ambient light</source>
        <translation>Ambientes Licht bearbeiten</translation>
    </message>
    <message>
        <source>Edit material</source>
        <translation>Material bearbeiten</translation>
    </message>
    <message>
        <source>Move object</source>
        <translation>Objekt verschieben</translation>
    </message>
    <message>
        <source>Add light</source>
        <translation>Lichtquelle hinzufügen</translation>
    </message>
    <message>
        <source>Remove light %1</source>
        <translation>Licht %1 entfernen</translation>
    </message>
</context>
<context>
    <name>SceneShaderFiles</name>
    <message>
        <source>Cannot save the %1 shader: %2</source>
        <translation>Shader %1 kann nicht gespeichert werden: %2</translation>
    </message>
    <message>
        <source>Kept your unsaved shader edits; the scene&apos;s shader files were not loaded</source>
        <translation>Ungespeicherte Shader-Änderungen behalten; die Shader-Dateien der Szene wurden nicht geladen</translation>
    </message>
    <message>
        <source>shaders.%1: %2: file not found</source>
        <translation>shaders.%1: %2: Datei nicht gefunden</translation>
    </message>
    <message>
        <source>shaders.%1: %2</source>
        <translation>shaders.%1: %2</translation>
    </message>
</context>
<context>
    <name>UniformOwner</name>
    <message>
        <source>set by the renderer</source>
        <translation>vom Renderer gesetzt</translation>
    </message>
    <message>
        <source>set by the scene (Material/Lights docks)</source>
        <translation>von der Szene gesetzt (Docks Material/Lichtquellen)</translation>
    </message>
</context>
<context>
    <name>phonglab::AboutDialog</name>
    <message>
        <source>PhongLab: %1</source>
        <translation>PhongLab: %1</translation>
    </message>
    <message>
        <source>unknown version</source>
        <translation>unbekannte Version</translation>
    </message>
    <message>
        <source>Qt: %1 (built against %2)</source>
        <translation>Qt: %1 (gebaut gegen %2)</translation>
    </message>
    <message>
        <source>OpenGL: %1</source>
        <translation>OpenGL: %1</translation>
    </message>
    <message>
        <source>not started yet (the 3D view has not drawn)</source>
        <translation>noch nicht gestartet (die 3D-Ansicht hat noch nicht gezeichnet)</translation>
    </message>
    <message>
        <source>OpenMesh: %1</source>
        <translation>OpenMesh: %1</translation>
    </message>
    <message>
        <source>Platform: %1, %2</source>
        <translation>Plattform: %1, %2</translation>
    </message>
    <message>
        <source>About PhongLab</source>
        <translation>Über PhongLab</translation>
    </message>
    <message>
        <source>&lt;h2&gt;PhongLab&lt;/h2&gt;&lt;p&gt;A shader editor for the Phong illumination model: edit the shaders while they run, and check them against the exact answer.&lt;/p&gt;&lt;p&gt;Free software under the GNU General Public License, version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;PhongLab&lt;/h2&gt;&lt;p&gt;Ein Shader-Editor für das Phong-Beleuchtungsmodell: Shader während der Ausführung bearbeiten und gegen das exakte Bild prüfen.&lt;/p&gt;&lt;p&gt;Freie Software unter der GNU General Public License, Version 3 oder neuer.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <source>Copy the versions, for a bug report</source>
        <translation>Versionen kopieren, für einen Fehlerbericht</translation>
    </message>
</context>
<context>
    <name>phonglab::AtomicFile</name>
    <message>
        <source>%1: cannot write: %2</source>
        <translation>%1: Schreiben nicht möglich: %2</translation>
    </message>
</context>
<context>
    <name>phonglab::BenchEngine</name>
    <message>
        <source>the bench has no OpenGL context (initialize() failed or was not called)</source>
        <translation>der Benchmark hat keinen OpenGL-Kontext (initialize() ist fehlgeschlagen oder wurde nicht aufgerufen)</translation>
    </message>
    <message>
        <source>%1: loading meshes</source>
        <translation>%1: Meshes werden geladen</translation>
    </message>
    <message>
        <source>%1: no reference: %2</source>
        <translation>%1: keine Referenz: %2</translation>
    </message>
    <message>
        <source>%1: no silhouette mask: %2</source>
        <translation>%1: keine Silhouettenmaske: %2</translation>
    </message>
    <message>
        <source>%1, per-object fit: %2</source>
        <translation>%1, Anpassung pro Objekt: %2</translation>
    </message>
    <message>
        <source>%1: detail %2 draws the same %3 triangles as the level before; skipped</source>
        <translation>%1: Detailstufe %2 zeichnet dieselben %3 Dreiecke wie die Stufe davor; übersprungen</translation>
    </message>
    <message>
        <source>%1 at detail %2: %3</source>
        <translation>%1 in Detailstufe %2: %3</translation>
    </message>
    <message>
        <source>%1: the shipped %2 shaders did not build: %3</source>
        <translation>%1: die mitgelieferten Shader für %2 ließen sich nicht bauen: %3</translation>
    </message>
</context>
<context>
    <name>phonglab::BenchPictures</name>
    <message>
        <source>CPU reference (exact)</source>
        <translation>CPU-Referenz (exakt)</translation>
    </message>
    <message>
        <source>error: green exact, yellow 4/255, red ≥ 8/255, blue silhouette band</source>
        <translation>Fehler: grün exakt, gelb 4/255, rot ≥ 8/255, blau Silhouettenrand</translation>
    </message>
</context>
<context>
    <name>phonglab::BenchProcess</name>
    <message>
        <source>a measurement is already running</source>
        <translation>eine Messung läuft bereits</translation>
    </message>
    <message>
        <source>no temporary folder for the measurement: %1</source>
        <translation>kein temporärer Ordner für die Messung: %1</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>could not run %1: %2</source>
        <translation>%1 konnte nicht ausgeführt werden: %2</translation>
    </message>
    <message>
        <source>the measurement stopped (exit %1)</source>
        <translation>die Messung wurde abgebrochen (Exit-Code %1)</translation>
    </message>
    <message>
        <source>the measurement wrote no results: %1</source>
        <translation>die Messung hat keine Ergebnisse geschrieben: %1</translation>
    </message>
</context>
<context>
    <name>phonglab::BenchResult</name>
    <message>
        <source>is not a number</source>
        <translation>ist keine Zahl</translation>
    </message>
    <message>
        <source>is not a whole number</source>
        <translation>ist keine ganze Zahl</translation>
    </message>
    <message>
        <source>is out of range</source>
        <translation>liegt außerhalb des gültigen Bereichs</translation>
    </message>
    <message>
        <source>is not 0 or 1</source>
        <translation>ist nicht 0 oder 1</translation>
    </message>
    <message>
        <source>%1 line %2: unbalanced quotes</source>
        <translation>%1 Zeile %2: Anführungszeichen nicht geschlossen</translation>
    </message>
    <message>
        <source>%1: empty file, expected a header line starting with &apos;%2&apos;</source>
        <translation>%1: leere Datei, Kopfzeile erwartet, die mit &apos;%2&apos; beginnt</translation>
    </message>
    <message>
        <source>%1 line %2: column &apos;%3&apos; appears twice</source>
        <translation>%1 Zeile %2: Spalte &apos;%3&apos; kommt zweimal vor</translation>
    </message>
    <message>
        <source>%1: expected %2 fields as in the header, found %3</source>
        <translation>%1: %2 Felder wie in der Kopfzeile erwartet, gefunden: %3</translation>
    </message>
    <message>
        <source>%1: method is empty</source>
        <translation>%1: method ist leer</translation>
    </message>
    <message>
        <source>%1 line %2: missing column %3</source>
        <translation>%1 Zeile %2: Spalte %3 fehlt</translation>
    </message>
    <message>
        <source>%1 line %2: missing columns %3</source>
        <translation>%1 Zeile %2: Spalten %3 fehlen</translation>
    </message>
</context>
<context>
    <name>phonglab::BindingChoice</name>
    <message>
        <source>automatic: %1</source>
        <translation>automatisch: %1</translation>
    </message>
    <message>
        <source>automatic: your own</source>
        <translation>automatisch: eigener Wert</translation>
    </message>
    <message>
        <source>your own</source>
        <translation>eigener Wert</translation>
    </message>
    <message>
        <source>PhongLab never sets it: you edit it here</source>
        <translation>PhongLab setzt diesen Wert nie: Er wird hier bearbeitet</translation>
    </message>
    <message>
        <source>What PhongLab sets %1 to (saved with the scene as &quot;bindings&quot;)</source>
        <translation>Der Wert, auf den PhongLab %1 setzt (mit der Szene unter &quot;bindings&quot; gespeichert)</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
</context>
<context>
    <name>phonglab::BindingConflicts</name>
    <message>
        <source>%1 is one colour for Id and Is (light-color), but light %2 of the scene has Id = %3 and Is = %4: give the light one colour in the scene, or bind %1 to Id or Is</source>
        <translation>%1 ist eine Farbe für Id und Is (light-color), aber Lichtquelle %2 der Szene hat Id = %3 und Is = %4: der Lichtquelle in der Szene eine Farbe geben oder %1 an Id oder Is binden</translation>
    </message>
    <message>
        <source>%1 is one colour for ka and kd (material-color), but object %2 of the scene has ka = %3 and kd = %4: give the material one colour in the scene, or bind %1 to ka or kd</source>
        <translation>%1 ist eine Farbe für ka und kd (material-color), aber Objekt %2 der Szene hat ka = %3 und kd = %4: dem Material in der Szene eine Farbe geben oder %1 an ka oder kd binden</translation>
    </message>
</context>
<context>
    <name>phonglab::BindingsByUse</name>
    <message>
        <source>the exponent of pow</source>
        <translation>der Exponent von pow</translation>
    </message>
    <message>
        <source>bounds the loop over the lights</source>
        <translation>begrenzt die Schleife über die Lichter</translation>
    </message>
    <message>
        <source>its place in the gl_Position chain (projection · view · model)</source>
        <translation>seine Stelle in der Kette von gl_Position (Projektion · View · Model)</translation>
    </message>
    <message>
        <source>subtracted from the surface position %1, as a light&apos;s position (world coordinates)</source>
        <translation>von der Oberflächenposition %1 abgezogen, als Position eines Lichts (Weltkoordinaten)</translation>
    </message>
    <message>
        <source>subtracted from the surface position %1, as the eye&apos;s</source>
        <translation>von der Oberflächenposition %1 abgezogen, als Position des Auges</translation>
    </message>
    <message>
        <source>scales the diffuse term</source>
        <translation>skaliert den diffusen Term</translation>
    </message>
    <message>
        <source>scales the specular term</source>
        <translation>skaliert den spekularen Term</translation>
    </message>
    <message>
        <source>scales the ambient term</source>
        <translation>skaliert den ambienten Term</translation>
    </message>
    <message>
        <source>holds the whole %1 beside the gain %2</source>
        <translation>hält das ganze %1 neben dem Faktor %2</translation>
    </message>
    <message>
        <source>moved into %1 and subtracted from the surface position %2, as a light&apos;s position (world coordinates)</source>
        <translation>nach %1 verschoben und von der Oberflächenposition %2 abgezogen, als Position eines Lichts (Weltkoordinaten)</translation>
    </message>
    <message>
        <source>moves the light&apos;s position into camera coordinates (%1)</source>
        <translation>bringt die Position des Lichts in Kamerakoordinaten (%1)</translation>
    </message>
    <message>
        <source>the term&apos;s only factor: %1</source>
        <translation>der einzige Faktor des Terms: %1</translation>
    </message>
    <message>
        <source>its columns scale the ambient, diffuse and specular terms in that order</source>
        <translation>seine Spalten skalieren den ambienten, diffusen und spekularen Term in dieser Reihenfolge</translation>
    </message>
</context>
<context>
    <name>phonglab::BrowserPipe</name>
    <message>
        <source>cannot make a pipe to the browser</source>
        <translation>keine Pipe zum Browser möglich</translation>
    </message>
    <message>
        <source>cannot start %1: %2</source>
        <translation>%1 lässt sich nicht starten: %2</translation>
    </message>
    <message>
        <source>the page did not finish within %1 s (a script that never ends, or a page that waits for something)</source>
        <translation>die Seite wurde nicht innerhalb von %1 s fertig (ein Skript, das nie endet, oder eine Seite, die auf etwas wartet)</translation>
    </message>
    <message>
        <source>the browser went away</source>
        <translation>der Browser ist weg</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>the browser did not start within %1 s</source>
        <translation>der Browser ist nicht innerhalb von %1 s gestartet</translation>
    </message>
</context>
<context>
    <name>phonglab::BuildStatusText</name>
    <message>
        <source>Compiling…</source>
        <translation>Wird kompiliert…</translation>
    </message>
    <message>
        <source>The new shader has not finished its first draw after %1 s (an endless loop?). It is marked: PhongLab will not run it by itself at the next start.</source>
        <translation>Der neue Shader hat sein erstes Zeichnen nach %1 s noch nicht beendet (eine Endlosschleife?). Er ist markiert: PhongLab führt ihn beim nächsten Start nicht von selbst aus.</translation>
    </message>
    <message>
        <source>Live editing is off: no OpenGL context could be shared with the build thread (%1)</source>
        <translation>Live-Bearbeitung ist ausgeschaltet: Mit dem Build-Thread konnte kein OpenGL-Kontext geteilt werden (%1)</translation>
    </message>
    <message>
        <source>Kept your unsaved shader edits; the scene&apos;s %1 shading was not loaded (choose it in the Shaders dock to switch)</source>
        <translation>Ungespeicherte Shader-Änderungen behalten; die %1-Schattierung der Szene wurde nicht geladen (zum Wechseln im Dock „Shader“ auswählen)</translation>
    </message>
    <message>
        <source>Kept out: one frame would take %1 ms or more (the budget is %2 ms, a few frames&apos; worth); the last good program keeps drawing</source>
        <translation>Nicht übernommen: Ein Frame würde %1 ms oder länger dauern (das Budget beträgt %2 ms, einige Frames); das letzte funktionierende Programm zeichnet weiter</translation>
    </message>
    <message>
        <source>Compiled in %1 ms (compile %2, link %3, first draw %4)</source>
        <translation>Kompiliert in %1 ms (Kompilieren %2, Linken %3, erstes Zeichnen %4)</translation>
    </message>
    <message numerus="yes">
        <source> — %n warning(s)</source>
        <translation>
            <numerusform> — %n Warnung</numerusform>
            <numerusform> — %n Warnungen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n error(s) — last good program still running</source>
        <translation>
            <numerusform>%n Fehler — letztes funktionierendes Programm läuft weiter</numerusform>
            <numerusform>%n Fehler — letztes funktionierendes Programm läuft weiter</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>phonglab::BuildThread</name>
    <message>
        <source>the viewport has no OpenGL context yet</source>
        <translation>die Ansicht hat noch keinen OpenGL-Kontext</translation>
    </message>
    <message>
        <source>the driver cannot create an OpenGL context sharing the viewport&apos;s</source>
        <translation>der Treiber kann keinen mit dem Kontext der Ansicht geteilten OpenGL-Kontext erstellen</translation>
    </message>
    <message>
        <source>cannot create an offscreen surface for the compile thread</source>
        <translation>für den Build-Thread kann keine Offscreen-Oberfläche erstellt werden</translation>
    </message>
    <message>
        <source>the build thread is not running</source>
        <translation>der Build-Thread läuft nicht</translation>
    </message>
</context>
<context>
    <name>phonglab::BuildWorker</name>
    <message>
        <source>the shared OpenGL context cannot be made current on the compile thread</source>
        <translation>der geteilte OpenGL-Kontext kann im Build-Thread nicht als aktueller Kontext gesetzt werden</translation>
    </message>
    <message>
        <source>the viewport&apos;s context cannot be made current on the build thread</source>
        <translation>der Kontext der Ansicht kann im Build-Thread nicht zum aktuellen Kontext gemacht werden</translation>
    </message>
</context>
<context>
    <name>phonglab::CameraPath</name>
    <message>
        <source>top level: expected a JSON object</source>
        <translation>oberste Ebene: JSON-Objekt erwartet</translation>
    </message>
    <message>
        <source>frames: expected a whole number from 2 to 10000</source>
        <translation>frames: ganze Zahl von 2 bis 10000 erwartet</translation>
    </message>
    <message>
        <source>keyframes: expected an array of at least 2 keyframes</source>
        <translation>keyframes: Array mit mindestens 2 Keyframes erwartet</translation>
    </message>
    <message>
        <source>: expected an object</source>
        <translation>: Objekt erwartet</translation>
    </message>
    <message>
        <source>.eye: required field missing</source>
        <translation>.eye: Pflichtfeld fehlt</translation>
    </message>
    <message>
        <source>.fov_deg: expected degrees in (0, 180)</source>
        <translation>.fov_deg: Grad im Bereich (0, 180) erwartet</translation>
    </message>
    <message>
        <source>: eye and target coincide, or up is along the view</source>
        <translation>: eye und target fallen zusammen, oder up liegt in Blickrichtung</translation>
    </message>
    <message>
        <source>frame %1, between keyframes[%2] and [%3]: eye and target coincide, or up is along the view</source>
        <translation>Frame %1, zwischen keyframes[%2] und [%3]: eye und target fallen zusammen, oder up liegt in Blickrichtung</translation>
    </message>
    <message>
        <source>%1.%2: expected 3 numbers, each at most 1e150 in size</source>
        <translation>%1.%2: 3 Zahlen erwartet, jede mit einem Betrag von höchstens 1e150</translation>
    </message>
    <message>
        <source>%1: cannot read camera path (%2)</source>
        <translation>%1: Kamerapfad kann nicht gelesen werden (%2)</translation>
    </message>
    <message>
        <source>%1: too large for a camera path</source>
        <translation>%1: zu groß für einen Kamerapfad</translation>
    </message>
</context>
<context>
    <name>phonglab::CaptureBounds</name>
    <message>
        <source>a negative first vertex</source>
        <translation>ein negativer erster Vertex</translation>
    </message>
    <message>
        <source>the index buffer does not hold %1 indices</source>
        <translation>der Indexpuffer enthält keine %1 Indizes</translation>
    </message>
    <message>
        <source>more vertices than PhongLab draws again</source>
        <translation>mehr Vertices, als PhongLab erneut zeichnet</translation>
    </message>
    <message>
        <source>attribute %1 has a layout PhongLab does not draw</source>
        <translation>Attribut %1 hat ein Layout, das PhongLab nicht zeichnet</translation>
    </message>
    <message>
        <source>attribute %1 reads no buffer</source>
        <translation>Attribut %1 liest aus keinem Puffer</translation>
    </message>
    <message>
        <source>attribute %1 reads %2 bytes of a buffer of %3</source>
        <translation>Attribut %1 liest %2 Bytes aus einem Puffer von %3</translation>
    </message>
    <message>
        <source>attribute %1 starts past its buffer</source>
        <translation>Attribut %1 beginnt hinter seinem Puffer</translation>
    </message>
</context>
<context>
    <name>phonglab::ChartImages</name>
    <message>
        <source>charts need a QApplication (Qt Charts are widgets)</source>
        <translation>Diagramme brauchen eine QApplication (Qt Charts sind Widgets)</translation>
    </message>
    <message>
        <source>no output file given</source>
        <translation>keine Ausgabedatei angegeben</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>PhongLab benchmark chart</source>
        <translation>PhongLab-Benchmark-Diagramm</translation>
    </message>
    <message>
        <source>cannot write %1: SVG output failed</source>
        <translation>%1 kann nicht geschrieben werden: SVG-Ausgabe fehlgeschlagen</translation>
    </message>
    <message>
        <source>nothing to draw</source>
        <translation>nichts zu zeichnen</translation>
    </message>
</context>
<context>
    <name>phonglab::CheckOverlay</name>
    <message>
        <source>exact</source>
        <translation>exakt</translation>
    </message>
    <message>
        <source>yours</source>
        <translation>eigenes</translation>
    </message>
    <message>
        <source>4/255</source>
        <translation>4/255</translation>
    </message>
    <message>
        <source>≥ 8/255</source>
        <translation>≥ 8/255</translation>
    </message>
    <message>
        <source>silhouette band, not checked</source>
        <translation>Silhouettenrand, nicht bewertet</translation>
    </message>
</context>
<context>
    <name>phonglab::CheckReportOutput</name>
    <message>
        <source>pass</source>
        <translation>bestanden</translation>
    </message>
    <message>
        <source>fail</source>
        <translation>nicht bestanden</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>%1 explains %2 % of the difference (%3): %4</source>
        <translation>%1 erklärt %2 % des Unterschieds (%3): %4</translation>
    </message>
    <message>
        <source>; or, with the same image, %1: %2</source>
        <translation>; oder, bei gleichem Bild, %1: %2</translation>
    </message>
    <message>
        <source>the background</source>
        <translation>Hintergrund</translation>
    </message>
    <message>
        <source>object %1 (%2)</source>
        <translation>Objekt %1 (%2)</translation>
    </message>
    <message>
        <source>no classic mistake explains the difference; the error heatmap (--diff) shows where it is</source>
        <translation>kein typischer Fehler erklärt den Unterschied; die Fehler-Heatmap (--diff) zeigt, wo er liegt</translation>
    </message>
    <message>
        <source>bindings: %1</source>
        <translation>Zuordnungen: %1</translation>
    </message>
    <message>
        <source>note: %1</source>
        <translation>Hinweis: %1</translation>
    </message>
    <message>
        <source>check: error</source>
        <translation>Prüfung: Fehler</translation>
    </message>
    <message>
        <source>check: %1</source>
        <translation>Prüfung: %1</translation>
    </message>
    <message>
        <source>%1, max error %2/255 (tolerance %3/255), %4 % of %5 compared pixels over it</source>
        <translation>%1, max. Fehler %2/255 (Toleranz %3/255), %4 % von %5 verglichenen Pixeln darüber</translation>
    </message>
    <message>
        <source>PSNR %1 dB</source>
        <translation>PSNR %1 dB</translation>
    </message>
    <message>
        <source>PSNR inf</source>
        <translation>PSNR inf</translation>
    </message>
    <message>
        <source>equation: the slide&apos;s, taken literally (a highlight even where N·L &lt;= 0), which is right too</source>
        <translation>Beleuchtungsgleichung: wörtlich wie auf der Folie (ein Glanzlicht auch dort, wo N·L &lt;= 0 ist); auch das ist richtig</translation>
    </message>
    <message>
        <source>worst pixel (%1, %2) on %3</source>
        <translation>schlechtestes Pixel (%1, %2): %3</translation>
    </message>
    <message>
        <source>diagnosis:</source>
        <translation>Diagnose:</translation>
    </message>
    <message>
        <source>  unknown: no classic mistake explains the difference; the heatmap (--diff) shows where it is</source>
        <translation>  unknown: kein typischer Fehler erklärt den Unterschied; die Heatmap (--diff) zeigt, wo er liegt</translation>
    </message>
    <message>
        <source>cannot show in this scene: %1</source>
        <translation>in dieser Szene nicht nachweisbar: %1</translation>
    </message>
    <message>
        <source>precision: %1 checked as written, as this driver computes it</source>
        <translation>Genauigkeit: %1 wie geschrieben beurteilt, so wie dieser Treiber rechnet</translation>
    </message>
    <message>
        <source>precision: %1 checked at highp (32-bit floats), as a desktop browser computes it; as written the program does not build on a driver that honours precision (a browser too): %2</source>
        <translation>Genauigkeit: %1 mit highp beurteilt (32-Bit-Gleitkommazahlen), so wie ein Desktop-Browser rechnet; wie geschrieben lässt sich das Programm auf einem Treiber, der die Genauigkeit einhält (auch in einem Browser), nicht bauen: %2</translation>
    </message>
    <message>
        <source>precision: %1 checked at highp (32-bit floats), as a desktop browser computes it</source>
        <translation>Genauigkeit: %1 mit highp beurteilt (32-Bit-Gleitkommazahlen), so wie ein Desktop-Browser rechnet</translation>
    </message>
    <message>
        <source>precision: %1 checked at highp (32-bit floats), as a desktop browser computes it; as written it draws the same image here</source>
        <translation>Genauigkeit: %1 mit highp beurteilt (32-Bit-Gleitkommazahlen), so wie ein Desktop-Browser rechnet; wie geschrieben zeichnet es hier dasselbe Bild</translation>
    </message>
    <message>
        <source>precision: %1 checked at highp (32-bit floats), as a desktop browser computes it; as written, on a driver that computes %1 in fewer bits (this one does), the image changes by up to %2/255 (PSNR %3 dB): not counted against the shader</source>
        <translation>Genauigkeit: %1 mit highp beurteilt (32-Bit-Gleitkommazahlen), so wie ein Desktop-Browser rechnet; wie geschrieben ändert sich das Bild auf einem Treiber, der %1 mit weniger Bits rechnet (wie dieser), um bis zu %2/255 (PSNR %3 dB): wird dem Shader nicht angerechnet</translation>
    </message>
    <message>
        <source>  together: %1 explain %2 % of the difference</source>
        <translation>  zusammen: %1 erklären %2 % des Unterschieds</translation>
    </message>
    <message>
        <source>  each alone:</source>
        <translation>  jeder für sich:</translation>
    </message>
    <message>
        <source>bound by use: %1</source>
        <translation>nach Verwendung gebunden: %1</translation>
    </message>
    <message>
        <source>%1: the vertex shader computes the lighting and the fragment shader interpolates it (its image alone explains %2 % of the difference): %3</source>
        <translation>%1: der Vertex-Shader berechnet die Beleuchtung und der Fragment-Shader interpoliert sie (ihr Bild allein erklärt %2 % des Unterschieds): %3</translation>
    </message>
    <message>
        <source>  closest, partial: %1 explain %2 % of the difference</source>
        <translation>  am nächsten, teilweise: %1 erklären %2 % des Unterschieds</translation>
    </message>
    <message>
        <source>  more than %1 deviations would be needed to explain all of it: the heatmap shows the rest</source>
        <translation>  mehr als %1 Abweichungen wären nötig, um alles zu erklären: die Heatmap zeigt den Rest</translation>
    </message>
    <message>
        <source>not checked in this scene: %1</source>
        <translation>in dieser Szene nicht geprüft: %1</translation>
    </message>
    <message>
        <source>timeout</source>
        <translation>Zeitüberschreitung</translation>
    </message>
    <message>
        <source>crash</source>
        <translation>Absturz</translation>
    </message>
</context>
<context>
    <name>phonglab::CoursePrelude</name>
    <message>
        <source>expected NAME=VALUE with NAME a GLSL identifier, got &apos;%1&apos;</source>
        <translation>NAME=VALUE erwartet, mit NAME als GLSL-Bezeichner, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: the value must be one line</source>
        <translation>&apos;%1&apos;: der Wert muss eine Zeile sein</translation>
    </message>
    <message>
        <source>three.js&apos;s ShaderMaterial prelude added (its built-in uniforms and attributes, precision highp), as three.js adds it</source>
        <translation>Vorspann von three.js&apos; ShaderMaterial hinzugefügt (seine eingebauten Uniform-Variablen und Attribute, precision highp), so wie three.js ihn hinzufügt</translation>
    </message>
    <message>
        <source>no default float precision: checked with &apos;precision highp float;&apos; added, as the page&apos;s JavaScript adds it</source>
        <translation>keine Standard-Genauigkeit für float: geprüft mit hinzugefügtem &apos;precision highp float;&apos;, so wie das JavaScript der Seite es hinzufügt</translation>
    </message>
    <message>
        <source>%1 checked at highp (32-bit floats), as a desktop browser computes it (--precision as-written for this driver&apos;s own)</source>
        <translation>%1 mit highp beurteilt (32-Bit-Gleitkommazahlen), so wie ein Desktop-Browser rechnet (--precision as-written für die Genauigkeit dieses Treibers)</translation>
    </message>
    <message>
        <source> (%1 is never defined: if the page&apos;s JavaScript replaces it before compiling, give its value with --define %1=VALUE or the scene&apos;s &quot;defines&quot;)</source>
        <translation> (%1 ist nirgends definiert: Ersetzt das JavaScript der Seite ihn vor dem Kompilieren, seinen Wert mit --define %1=VALUE oder in den &quot;defines&quot; der Szene angeben)</translation>
    </message>
</context>
<context>
    <name>phonglab::DepthRange</name>
    <message>
        <source>surfaces closer than about %1 % of their distance may show through each other</source>
        <translation>Oberflächen, die näher als etwa %1 % ihrer Entfernung beieinanderliegen, können durcheinander hindurchscheinen</translation>
    </message>
    <message>
        <source>the depth buffer cannot tell surfaces apart</source>
        <translation>der Tiefenpuffer kann die Oberflächen nicht unterscheiden</translation>
    </message>
    <message>
        <source>camera: near %1 and far %2 are %3 orders of magnitude apart (the eye is inside an object&apos;s bounds); %4: raise near</source>
        <translation>camera: near %1 und far %2 liegen %3 Größenordnungen auseinander (das Auge liegt innerhalb der Ausdehnung eines Objekts); %4: near erhöhen</translation>
    </message>
</context>
<context>
    <name>phonglab::DetailLevelLabel</name>
    <message>
        <source>&quot;detail&quot;: &quot;auto&quot;: the level each object is drawn at, chosen from its size on screen within the Performance dock&apos;s budget</source>
        <translation>&quot;detail&quot;: &quot;auto&quot;: die Detailstufe, in der jedes Objekt gezeichnet wird, gewählt nach seiner Größe auf dem Bildschirm im Rahmen des Budgets aus dem Leistungs-Dock</translation>
    </message>
</context>
<context>
    <name>phonglab::DocumentationBrowser</name>
    <message>
        <source>PhongLab Documentation</source>
        <translation>PhongLab-Dokumentation</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Vorwärts</translation>
    </message>
    <message>
        <source>Contents</source>
        <translation>Inhalt</translation>
    </message>
    <message>
        <source>%1 is not part of the documentation installed here (%2).</source>
        <translation>%1 gehört nicht zur hier installierten Dokumentation (%2).</translation>
    </message>
    <message>
        <source>%1 — PhongLab Documentation</source>
        <translation>%1 — PhongLab-Dokumentation</translation>
    </message>
</context>
<context>
    <name>phonglab::ErrorBudget</name>
    <message>
        <source>%1 at full detail</source>
        <translation>%1 in voller Detailstufe</translation>
    </message>
    <message>
        <source>%1 at detail %2</source>
        <translation>%1 in Detailstufe %2</translation>
    </message>
    <message>
        <source>max error %1/255</source>
        <translation>max. Fehler %1/255</translation>
    </message>
    <message>
        <source>max error ≤ %1/255</source>
        <translation>max. Fehler ≤ %1/255</translation>
    </message>
    <message>
        <source>nothing meets %1: no measured rows</source>
        <translation>nichts erfüllt %1: keine gemessenen Zeilen</translation>
    </message>
    <message>
        <source>nothing meets %1: the best measured was %2 (%3)</source>
        <translation>nichts erfüllt %1: das beste gemessene Ergebnis war %2 (%3)</translation>
    </message>
    <message>
        <source>%1 (%2) meets %3; %4; no full-detail Phong row to compare against</source>
        <translation>%1 (%2) erfüllt %3; %4; keine Phong-Zeile in voller Detailstufe zum Vergleich</translation>
    </message>
    <message>
        <source>%1 is the cheapest that meets %2; %3</source>
        <translation>%1 ist die günstigste Variante, die %2 erfüllt; %3</translation>
    </message>
    <message>
        <source>%1 more triangles</source>
        <translation>%1 Dreiecke mehr</translation>
    </message>
    <message>
        <source>%1 ms more</source>
        <translation>%1 ms mehr</translation>
    </message>
    <message>
        <source>costs </source>
        <translation>kostet </translation>
    </message>
    <message>
        <source> but costs </source>
        <translation> kostet aber </translation>
    </message>
    <message>
        <source>saves nothing</source>
        <translation>spart nichts</translation>
    </message>
    <message>
        <source>%1 triangles, %2 ms</source>
        <translation>%1 Dreiecke, %2 ms</translation>
    </message>
    <message>
        <source>full-detail %1 (%2)</source>
        <translation>%1 in voller Detailstufe (%2)</translation>
    </message>
    <message>
        <source>%1 triangles</source>
        <translation>%1 Dreiecke</translation>
    </message>
    <message>
        <source>saves %1</source>
        <translation>spart %1</translation>
    </message>
    <message>
        <source> and </source>
        <translation> und </translation>
    </message>
</context>
<context>
    <name>phonglab::ExamplesMenu</name>
    <message>
        <source>Tree and Cloud (the default)</source>
        <translation>Baum und Wolke (Standard)</translation>
    </message>
    <message>
        <source>Two Spheres (the check scene)</source>
        <translation>Zwei Kugeln (die Prüfszene)</translation>
    </message>
    <message>
        <source>Grazing Light on a Box</source>
        <translation>Streiflicht auf einem Quader</translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <source>Torus</source>
        <translation>Torus</translation>
    </message>
</context>
<context>
    <name>phonglab::FileMenu</name>
    <message>
        <source>&amp;Open Scene…</source>
        <translation>Szene ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Open &amp;Mesh…</source>
        <translation>&amp;Mesh öffnen…</translation>
    </message>
    <message>
        <source>Ctrl+Shift+O</source>
        <translation>Ctrl+Shift+O</translation>
    </message>
    <message>
        <source>&amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>E&amp;xamples</source>
        <translation>Beis&amp;piele</translation>
    </message>
    <message>
        <source>&amp;Save Scene</source>
        <translation>Szene &amp;speichern</translation>
    </message>
    <message>
        <source>Save Scene &amp;As…</source>
        <translation>Szene speichern &amp;unter…</translation>
    </message>
    <message>
        <source>Ctrl+Shift+S</source>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <source>&amp;Export Image…</source>
        <translation>Bild e&amp;xportieren…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>Ctrl+Q</source>
        <translation>Ctrl+Q</translation>
    </message>
    <message>
        <source>Cannot open: %1</source>
        <translation>Öffnen nicht möglich: %1</translation>
    </message>
    <message>
        <source>Cannot open</source>
        <translation>Öffnen nicht möglich</translation>
    </message>
    <message>
        <source>%1

The current scene is still open.</source>
        <translation>%1

Die aktuelle Szene bleibt geöffnet.</translation>
    </message>
    <message>
        <source>Open Scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <source>Open Mesh</source>
        <translation>Mesh öffnen</translation>
    </message>
    <message>
        <source>File not found</source>
        <translation>Datei nicht gefunden</translation>
    </message>
    <message>
        <source>%1

The file no longer exists; it was removed from the recent files.</source>
        <translation>%1

Die Datei existiert nicht mehr; sie wurde aus der Liste der zuletzt geöffneten Dateien entfernt.</translation>
    </message>
    <message>
        <source>Save Scene As</source>
        <translation>Szene speichern unter</translation>
    </message>
    <message>
        <source>Cannot save scene</source>
        <translation>Szene kann nicht gespeichert werden</translation>
    </message>
    <message>
        <source>%1

%2</source>
        <translation>%1

%2</translation>
    </message>
    <message>
        <source>Export Image</source>
        <translation>Bild exportieren</translation>
    </message>
    <message>
        <source>Width (pixels):</source>
        <translation>Breite (Pixel):</translation>
    </message>
    <message>
        <source>Height (pixels):</source>
        <translation>Höhe (Pixel):</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <source>Open &amp;Project…</source>
        <translation>&amp;Projekt öffnen…</translation>
    </message>
    <message>
        <source>Open WebGL Project</source>
        <translation>WebGL-Projekt öffnen</translation>
    </message>
    <message>
        <source>WebGL projects (*.html *.htm *.js *.mjs);;All files (*)</source>
        <translation>WebGL-Projekte (*.html *.htm *.js *.mjs);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>The project has several programs that light. Which one?</source>
        <translation>Das Projekt hat mehrere Programme, die beleuchten. Welches?</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>The shaders have unsaved changes. Discard them?</source>
        <translation>Die Shader haben ungespeicherte Änderungen. Verwerfen?</translation>
    </message>
    <message>
        <source>Opened %1 of %2</source>
        <translation>%1 aus %2 geöffnet</translation>
    </message>
    <message>
        <source>Open S&amp;hader…</source>
        <translation>S&amp;hader öffnen…</translation>
    </message>
    <message>
        <source>Open Project &amp;Folder…</source>
        <translation>Projekt&amp;ordner öffnen…</translation>
    </message>
    <message>
        <source>Open Shader</source>
        <translation>Shader öffnen</translation>
    </message>
    <message>
        <source>Open WebGL Project Folder</source>
        <translation>WebGL-Projektordner öffnen</translation>
    </message>
    <message>
        <source>&amp;Run the Page…</source>
        <translation>Seite &amp;ausführen…</translation>
    </message>
    <message>
        <source>Run a WebGL Project&apos;s Page</source>
        <translation>Seite eines WebGL-Projekts ausführen</translation>
    </message>
</context>
<context>
    <name>phonglab::FrameRedraw</name>
    <message>
        <source>the driver gave no reason</source>
        <translation>der Treiber nannte keinen Grund</translation>
    </message>
    <message>
        <source>the frame could not be drawn at %1x%2</source>
        <translation>das Bild konnte nicht in %1x%2 gezeichnet werden</translation>
    </message>
    <message>
        <source>the program would not build again for the check: %1</source>
        <translation>das Programm ließ sich für die Prüfung nicht erneut bauen: %1</translation>
    </message>
</context>
<context>
    <name>phonglab::FrameStatsLabel</name>
    <message>
        <source>draw %1 ms · %2 triangles%3</source>
        <translation>Zeichnen %1 ms · %2 Dreiecke%3</translation>
    </message>
    <message>
        <source> · low depth precision</source>
        <translation> · geringe Tiefengenauigkeit</translation>
    </message>
    <message numerus="yes">
        <source>Draw time per frame: from the frame&apos;s first OpenGL call to glFinish, the scene and anything drawn over it (presenting the frame is not included); the mean of the %n frame(s) of the last second.</source>
        <translation>
            <numerusform>Zeichenzeit pro Frame: vom ersten OpenGL-Aufruf des Frames bis glFinish, die Szene und alles darüber Gezeichnete (das Anzeigen des Frames ist nicht enthalten); der Mittelwert über %n Frame der letzten Sekunde.</numerusform>
            <numerusform>Zeichenzeit pro Frame: vom ersten OpenGL-Aufruf des Frames bis glFinish, die Szene und alles darüber Gezeichnete (das Anzeigen des Frames ist nicht enthalten); der Mittelwert über %n Frames der letzten Sekunde.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>phonglab::GlslLexer</name>
    <message>
        <source>Keyword, qualifier or type</source>
        <translation>Schlüsselwort, Qualifizierer oder Typ</translation>
    </message>
    <message>
        <source>Built-in function or variable</source>
        <translation>Built-In-Funktion oder -Variable</translation>
    </message>
</context>
<context>
    <name>phonglab::GpuMesh</name>
    <message>
        <source>the driver cannot create a vertex array or buffer</source>
        <translation>der Treiber kann kein Vertex-Array oder Buffer-Objekt erstellen</translation>
    </message>
    <message>
        <source>no mesh uploaded</source>
        <translation>kein Mesh hochgeladen</translation>
    </message>
    <message>
        <source>the mesh is too large to read back for flat shading</source>
        <translation>das Mesh ist zu groß, um es für die flache Schattierung zurückzulesen</translation>
    </message>
    <message>
        <source>the driver cannot read the mesh back for flat shading</source>
        <translation>der Treiber kann das Mesh für die flache Schattierung nicht zurücklesen</translation>
    </message>
</context>
<context>
    <name>phonglab::GpuScene</name>
    <message>
        <source>Cannot build the %1 shading program:
%2</source>
        <translation>Das Programm für das Schattierungsverfahren %1 kann nicht gebaut werden:
%2</translation>
    </message>
    <message>
        <source>%1: mesh was not loaded</source>
        <translation>%1: Mesh wurde nicht geladen</translation>
    </message>
</context>
<context>
    <name>phonglab::GuiArguments</name>
    <message>
        <source>%1 needs a file</source>
        <translation>%1 braucht eine Datei</translation>
    </message>
    <message>
        <source>--vertex and --fragment open one scene with those shaders: phonglab SCENE.json --vertex FILE --fragment FILE</source>
        <translation>--vertex und --fragment öffnen eine Szene mit diesen Shadern: phonglab SCENE.json --vertex FILE --fragment FILE</translation>
    </message>
    <message>
        <source>--project takes both stages from the project; leave out --vertex and --fragment</source>
        <translation>--project nimmt beide Stufen aus dem Projekt; --vertex und --fragment weglassen</translation>
    </message>
    <message>
        <source>--program names a program of --project</source>
        <translation>--program nennt ein Programm von --project</translation>
    </message>
</context>
<context>
    <name>phonglab::HelpMenu</name>
    <message>
        <source>&amp;Documentation</source>
        <translation>&amp;Dokumentation</translation>
    </message>
    <message>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <source>&amp;About PhongLab</source>
        <translation>Ü&amp;ber PhongLab</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>The documentation (README.md and docs/*.md) is in none of these folders:

%1

Set PHONGLAB_DOC_DIR to the folder that holds it.</source>
        <translation>Die Dokumentation (README.md und docs/*.md) liegt in keinem dieser Ordner:

%1

Bitte PHONGLAB_DOC_DIR auf den Ordner setzen, der sie enthält.</translation>
    </message>
    <message>
        <source>Documentation not found</source>
        <translation>Dokumentation nicht gefunden</translation>
    </message>
</context>
<context>
    <name>phonglab::ImageMetrics</name>
    <message>
        <source>no pixels compared</source>
        <translation>keine Pixel verglichen</translation>
    </message>
    <message>
        <source>PSNR %1 dB, RMSE %2, max %3/255 at (%4,%5), %6 px</source>
        <translation>PSNR %1 dB, RMSE %2, max. %3/255 bei (%4,%5), %6 px</translation>
    </message>
</context>
<context>
    <name>phonglab::JsonText</name>
    <message>
        <source>JSON syntax error at line %1, column %2 (byte offset %3): %4</source>
        <translation>JSON-Syntaxfehler in Zeile %1, Spalte %2 (Byte-Offset %3): %4</translation>
    </message>
    <message>
        <source>out-of-range number %1</source>
        <translation>Zahl außerhalb des Wertebereichs %1</translation>
    </message>
</context>
<context>
    <name>phonglab::LabelledChart</name>
    <message>
        <source>log; 0 drawn at %1</source>
        <translation>log; 0 bei %1 dargestellt</translation>
    </message>
    <message>
        <source>Pareto front</source>
        <translation>Pareto-Front</translation>
    </message>
    <message>
        <source>Pareto front (points)</source>
        <translation>Pareto-Front (Punkte)</translation>
    </message>
</context>
<context>
    <name>phonglab::Language</name>
    <message>
        <source>--lang needs a language: en or de</source>
        <translation>--lang braucht eine Sprache: en oder de</translation>
    </message>
    <message>
        <source>--lang: PhongLab does not speak &apos;%1&apos; (en or de)</source>
        <translation>--lang: PhongLab spricht &apos;%1&apos; nicht (en oder de)</translation>
    </message>
</context>
<context>
    <name>phonglab::LanguageMenu</name>
    <message>
        <source>PhongLab speaks %1.</source>
        <translation>PhongLab spricht %1.</translation>
    </message>
    <message>
        <source>PhongLab will speak %1 from the next start.</source>
        <translation>PhongLab spricht ab dem nächsten Start %1.</translation>
    </message>
</context>
<context>
    <name>phonglab::LightsDock</name>
    <message>
        <source>c1 + c2 + c3 must be positive (got %1)</source>
        <translation>c1 + c2 + c3 muss positiv sein (erhalten: %1)</translation>
    </message>
    <message>
        <source>Lights</source>
        <translation>Lichtquellen</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Position (world)</source>
        <translation>Position (Weltkoordinaten)</translation>
    </message>
    <message>
        <source>Id (diffuse)</source>
        <translation>Id (diffus)</translation>
    </message>
    <message>
        <source>Is (specular)</source>
        <translation>Is (spekular)</translation>
    </message>
    <message>
        <source>c1, c2, c3</source>
        <translation>c1, c2, c3</translation>
    </message>
    <message>
        <source>Ambient Ia</source>
        <translation>Ambiente Intensität Ia</translation>
    </message>
    <message>
        <source>Headlight: follows the camera (not in world space, not saved)</source>
        <translation>Kopflicht: folgt der Kamera (nicht in Weltkoordinaten, wird nicht gespeichert)</translation>
    </message>
    <message>
        <source>Add Light</source>
        <translation>Lichtquelle hinzufügen</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Light %1</source>
        <translation>Licht %1</translation>
    </message>
</context>
<context>
    <name>phonglab::LiveCheck</name>
    <message>
        <source>check: waiting for the first frame</source>
        <translation>Prüfung: wartet auf das erste Bild</translation>
    </message>
    <message>
        <source>Pi&amp;xel Inspector</source>
        <translation>Pi&amp;xel-Inspektor</translation>
    </message>
    <message>
        <source>&amp;Check Toolbar</source>
        <translation>Prüfungs-&amp;Werkzeugleiste</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>Prüfung</translation>
    </message>
    <message>
        <source> Overlay: </source>
        <translation> Overlay: </translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>Error heatmap</source>
        <translation>Fehler-Heatmap</translation>
    </message>
    <message>
        <source>Split: exact | yours</source>
        <translation>Geteilt: exakt | eigenes</translation>
    </message>
    <message>
        <source>Exact</source>
        <translation>Exaktes Bild</translation>
    </message>
    <message>
        <source>Compare the view with the exact image of the illumination equation</source>
        <translation>Die Ansicht mit dem exakten Bild der Beleuchtungsgleichung vergleichen</translation>
    </message>
    <message>
        <source>Inspect</source>
        <translation>Inspizieren</translation>
    </message>
    <message>
        <source>Click a pixel to see the terms of the equation there (or Ctrl+click) [I]</source>
        <translation>Auf ein Pixel klicken, um dort die Anteile der Gleichung zu sehen (oder Ctrl+Klick) [I]</translation>
    </message>
    <message>
        <source>checking…</source>
        <translation>Prüfung läuft…</translation>
    </message>
    <message>
        <source>Checking the current view; the pixel is shown when that is done.</source>
        <translation>Die aktuelle Ansicht wird geprüft; das Pixel wird danach angezeigt.</translation>
    </message>
    <message>
        <source>Pixel (%1, %2) shows the background: no surface, no equation.</source>
        <translation>Pixel (%1, %2) zeigt den Hintergrund: keine Oberfläche, keine Gleichung.</translation>
    </message>
    <message>
        <source>checking… %1 %</source>
        <translation>Prüfung läuft… %1 %</translation>
    </message>
    <message>
        <source>Check &amp;Verdict</source>
        <translation>&amp;Prüfungsergebnis</translation>
    </message>
</context>
<context>
    <name>phonglab::LoadProgressWidget</name>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Stop loading and keep the current scene</source>
        <translation>Laden abbrechen und die aktuelle Szene behalten</translation>
    </message>
    <message>
        <source>Loading %1</source>
        <translation>%1 wird geladen</translation>
    </message>
</context>
<context>
    <name>phonglab::MainWindow</name>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>One frame took %1 ms: the view draws again when you click, scroll or press a key in it</source>
        <translation>Ein Frame dauerte %1 ms: Die Ansicht zeichnet erst wieder, wenn in ihr geklickt, gescrollt oder eine Taste gedrückt wird</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>OpenGL not started</source>
        <translation>OpenGL nicht gestartet</translation>
    </message>
    <message>
        <source>Rendering failed: %1</source>
        <translation>Rendern fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Rendering failed</source>
        <translation>Rendern fehlgeschlagen</translation>
    </message>
</context>
<context>
    <name>phonglab::MaterialDock</name>
    <message>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <source>ka (ambient)</source>
        <translation>ka (ambient)</translation>
    </message>
    <message>
        <source>kd (diffuse)</source>
        <translation>kd (diffus)</translation>
    </message>
    <message>
        <source>ks (specular)</source>
        <translation>ks (spekular)</translation>
    </message>
    <message>
        <source>Shininess n</source>
        <translation>Glanzexponent n</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <source>Save as Preset…</source>
        <translation>Als Vorlage speichern…</translation>
    </message>
    <message>
        <source>Preset</source>
        <translation>Vorlage</translation>
    </message>
    <message>
        <source>Save Material Preset</source>
        <translation>Materialvorlage speichern</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
</context>
<context>
    <name>phonglab::MaterialPresets</name>
    <message>
        <source>Plastic</source>
        <translation>Kunststoff</translation>
    </message>
    <message>
        <source>Rubber</source>
        <translation>Gummi</translation>
    </message>
    <message>
        <source>Polished metal</source>
        <translation>Poliertes Metall</translation>
    </message>
    <message>
        <source>Chalk</source>
        <translation>Kreide</translation>
    </message>
</context>
<context>
    <name>phonglab::MeshBuilder</name>
    <message>
        <source>%1 of %2 corners have a zero or invalid normal in the file; computed angle-weighted normals replace them</source>
        <translation>%1 von %2 Ecken haben in der Datei eine Null- oder ungültige Normale; sie werden durch berechnete, winkelgewichtete Normalen ersetzt</translation>
    </message>
    <message>
        <source>the mesh has no faces</source>
        <translation>das Mesh hat keine Flächen</translation>
    </message>
    <message>
        <source>the mesh is too large: %1 triangles exceed what 32-bit indices can address</source>
        <translation>das Mesh ist zu groß: %1 Dreiecke übersteigen, was 32-Bit-Indizes adressieren können</translation>
    </message>
    <message>
        <source>%1 polygons cross or fold onto themselves; they were split as fans</source>
        <translation>%1 Polygone überschneiden sich selbst oder sind in sich gefaltet; sie wurden als Fächer zerlegt</translation>
    </message>
    <message>
        <source>%1 of %2 corners have no normal in the file; computed angle-weighted normals for the whole mesh</source>
        <translation>%1 von %2 Ecken haben in der Datei keine Normale; für das ganze Mesh wurden winkelgewichtete Normalen berechnet</translation>
    </message>
</context>
<context>
    <name>phonglab::MeshDecimation</name>
    <message>
        <source>detail must be in (0, 1] (got %1); mesh left as it is</source>
        <translation>detail muss in (0, 1] liegen (erhalten: %1); Mesh bleibt unverändert</translation>
    </message>
    <message>
        <source>invalid mesh (index out of range or normals missing); not decimated</source>
        <translation>ungültiges Mesh (Index außerhalb des Bereichs oder Normalen fehlen); nicht reduziert</translation>
    </message>
    <message>
        <source>no triangle could be taken for decimation (all degenerate, non-finite or non-manifold); mesh left as it is</source>
        <translation>kein Dreieck für die Reduktion verwendbar (alle entartet, nicht endlich oder nicht mannigfaltig); Mesh bleibt unverändert</translation>
    </message>
    <message>
        <source>%1 non-manifold triangles (an edge with more than two faces, or a vertex joining separate fans) could not be decimated and were left out</source>
        <translation>%1 nicht-mannigfaltige Dreiecke (eine Kante mit mehr als zwei Flächen oder ein Vertex, der getrennte Fächer verbindet) konnten nicht reduziert werden und wurden ausgelassen</translation>
    </message>
    <message>
        <source>%1 triangles with non-finite corners left out</source>
        <translation>%1 Dreiecke mit nicht endlichen Ecken ausgelassen</translation>
    </message>
    <message>
        <source>decimation stopped at %1 triangles (asked for %2): every further collapse would fold a face or break the surface</source>
        <translation>Reduktion bei %1 Dreiecken beendet (angefordert: %2): jede weitere Kantenkontraktion würde eine Fläche umklappen oder die Oberfläche aufreißen</translation>
    </message>
</context>
<context>
    <name>phonglab::MeshFilePrecheck</name>
    <message>
        <source>rename it to .off</source>
        <translation>in .off umbenennen</translation>
    </message>
    <message>
        <source>an ascii STL file</source>
        <translation>eine ASCII-STL-Datei</translation>
    </message>
    <message>
        <source>rename it to .stl</source>
        <translation>in .stl umbenennen</translation>
    </message>
    <message>
        <source>this is %1, not a %2 file</source>
        <translation>dies ist %1, keine %2-Datei</translation>
    </message>
    <message>
        <source>three numbers after &apos;facet normal&apos;</source>
        <translation>drei Zahlen nach &apos;facet normal&apos;</translation>
    </message>
    <message>
        <source>the file ends inside facet %1 (truncated?)</source>
        <translation>die Datei endet innerhalb von Facette %1 (abgeschnitten?)</translation>
    </message>
    <message>
        <source>&apos;vertex x y z&apos;</source>
        <translation>&apos;vertex x y z&apos;</translation>
    </message>
    <message>
        <source>the STL file has no facets</source>
        <translation>die STL-Datei enthält keine Facetten</translation>
    </message>
    <message>
        <source>dropped %1 with NaN or infinite coordinates</source>
        <translation>%1 mit NaN- oder unendlichen Koordinaten verworfen</translation>
    </message>
    <message>
        <source>every triangle has NaN or infinite coordinates</source>
        <translation>jedes Dreieck hat NaN- oder unendliche Koordinaten</translation>
    </message>
    <message>
        <source>too small for a binary STL file (%1 bytes) and not an ascii one</source>
        <translation>zu klein für eine binäre STL-Datei (%1 Byte) und keine ASCII-STL-Datei</translation>
    </message>
    <message>
        <source>the binary STL header declares %1 triangles (%2 bytes) but the file has only %3 bytes (truncated or not an STL file)</source>
        <translation>der binäre STL-Header gibt %1 Dreiecke (%2 Byte) an, die Datei hat aber nur %3 Byte (abgeschnitten oder keine STL-Datei)</translation>
    </message>
    <message>
        <source>ignored %1 after the last triangle</source>
        <translation>%1 nach dem letzten Dreieck ignoriert</translation>
    </message>
    <message>
        <source>the STL file has no triangles</source>
        <translation>die STL-Datei enthält keine Dreiecke</translation>
    </message>
    <message>
        <source>not an OpenMesh file (it does not start with &apos;OM&apos;)</source>
        <translation>keine OpenMesh-Datei (beginnt nicht mit &apos;OM&apos;)</translation>
    </message>
    <message>
        <source>file not found</source>
        <translation>Datei nicht gefunden</translation>
    </message>
    <message>
        <source>not a regular file</source>
        <translation>keine reguläre Datei</translation>
    </message>
    <message>
        <source>cannot open the file: %1</source>
        <translation>Datei kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>die Datei ist leer</translation>
    </message>
    <message>
        <source>the file is too large (%1 MiB; the limit is %2 MiB)</source>
        <translation>die Datei ist zu groß (%1 MiB; die Grenze liegt bei %2 MiB)</translation>
    </message>
    <message>
        <source>cannot read the file: %1</source>
        <translation>Datei kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>not a PLY file (it does not start with &apos;ply&apos;)</source>
        <translation>keine PLY-Datei (sie beginnt nicht mit &apos;ply&apos;)</translation>
    </message>
    <message>
        <source>not an OFF file (it does not start with an OFF header)</source>
        <translation>keine OFF-Datei (sie beginnt nicht mit einem OFF-Header)</translation>
    </message>
    <message>
        <source>the file got shorter while it was read</source>
        <translation>die Datei wurde während des Lesens kürzer</translation>
    </message>
</context>
<context>
    <name>phonglab::MeshFileReader</name>
    <message>
        <source>the file has no faces</source>
        <translation>die Datei enthält keine Flächen</translation>
    </message>
    <message>
        <source>unsupported file type &apos;%1&apos; (supported: %2)</source>
        <translation>nicht unterstützter Dateityp &apos;%1&apos; (unterstützt: %2)</translation>
    </message>
    <message>
        <source>no suffix</source>
        <translation>keine Dateiendung</translation>
    </message>
    <message>
        <source>out of memory while reading the file</source>
        <translation>Arbeitsspeicher beim Lesen der Datei erschöpft</translation>
    </message>
    <message>
        <source>reading failed: %1</source>
        <translation>Lesen fehlgeschlagen: %1</translation>
    </message>
</context>
<context>
    <name>phonglab::MeshImportProcess</name>
    <message>
        <source>the reader used up its %1 s of CPU time and was stopped</source>
        <translation>der Leseprozess hat seine %1 s CPU-Zeit aufgebraucht und wurde beendet</translation>
    </message>
    <message>
        <source>the reader crashed with signal %1 (%2)</source>
        <translation>der Leseprozess ist mit Signal %1 (%2) abgestürzt</translation>
    </message>
    <message>
        <source>the reader ran out of memory (limit %1 MB)</source>
        <translation>dem Leseprozess ging der Speicher aus (Grenze: %1 MB)</translation>
    </message>
    <message>
        <source>the reader exited with status %1 without a result</source>
        <translation>der Leseprozess wurde mit Exit-Code %1 ohne Ergebnis beendet</translation>
    </message>
    <message>
        <source>cannot find the phonglab executable that imports meshes (set PHONGLAB_EXE)</source>
        <translation>das phonglab-Programm, das Meshes importiert, wurde nicht gefunden (PHONGLAB_EXE setzen)</translation>
    </message>
    <message>
        <source>cannot create a temporary file for the import</source>
        <translation>für den Import kann keine temporäre Datei angelegt werden</translation>
    </message>
    <message>
        <source>cannot start the import process %1: %2</source>
        <translation>der Importprozess %1 kann nicht gestartet werden: %2</translation>
    </message>
    <message>
        <source>%1: the reader stopped answering after %2 s and was stopped; the file is probably malformed</source>
        <translation>%1: der Leseprozess hat nach %2 s nicht mehr geantwortet und wurde beendet; die Datei ist vermutlich fehlerhaft</translation>
    </message>
    <message>
        <source>the import process gave no readable result</source>
        <translation>der Importprozess lieferte kein lesbares Ergebnis</translation>
    </message>
    <message>
        <source>cannot write the result to %1</source>
        <translation>das Ergebnis kann nicht nach %1 geschrieben werden</translation>
    </message>
</context>
<context>
    <name>phonglab::MeshLoader</name>
    <message>
        <source>%1: unknown builtin mesh (known: builtin:sphere, builtin:torus, builtin:cube)</source>
        <translation>%1: unbekanntes eingebautes Mesh (bekannt: builtin:sphere, builtin:torus, builtin:cube)</translation>
    </message>
    <message>
        <source>%1: no usable faces</source>
        <translation>%1: keine verwendbaren Flächen</translation>
    </message>
</context>
<context>
    <name>phonglab::MeshRaycaster</name>
    <message>
        <source>The scene has %1 objects but %2 meshes were given</source>
        <translation>Die Szene hat %1 Objekte, es wurden aber %2 Meshes übergeben</translation>
    </message>
    <message>
        <source>Object %1: mesh &quot;%2&quot; was given no triangle mesh and has no analytic surface (builtin:sphere, builtin:torus, builtin:cube)</source>
        <translation>Objekt %1: für Mesh &quot;%2&quot; wurde kein Dreiecks-Mesh übergeben, und es hat keine analytische Oberfläche (builtin:sphere, builtin:torus, builtin:cube)</translation>
    </message>
    <message>
        <source>Object %1: the triangle mesh for &quot;%2&quot; is not valid</source>
        <translation>Objekt %1: das Dreiecks-Mesh für &quot;%2&quot; ist ungültig</translation>
    </message>
    <message>
        <source>Invalid reference image size %1x%2</source>
        <translation>Ungültige Größe des Referenzbilds %1x%2</translation>
    </message>
</context>
<context>
    <name>phonglab::MeshRepair</name>
    <message>
        <source>dropped %1 with out-of-range vertex indices</source>
        <translation>%1 mit Vertex-Indizes außerhalb des gültigen Bereichs verworfen</translation>
    </message>
    <message>
        <source>dropped %1 using NaN or infinite coordinates</source>
        <translation>%1 mit NaN- oder unendlichen Koordinaten verworfen</translation>
    </message>
    <message>
        <source>dropped %1 (fewer than 3 distinct corners or zero area)</source>
        <translation>%1 verworfen (weniger als 3 verschiedene Ecken oder Flächeninhalt null)</translation>
    </message>
    <message>
        <source>ignored the file normal of %1 (missing, zero or not finite); computed instead</source>
        <translation>Normale aus der Datei für %1 ignoriert (fehlend, null oder nicht endlich); stattdessen berechnet</translation>
    </message>
    <message>
        <source>%1 (shared by 3 or more faces), kept as they are</source>
        <translation>%1 (von 3 oder mehr Flächen geteilt), unverändert belassen</translation>
    </message>
    <message>
        <source>%1 no consistent winding agrees on (a non-orientable surface)</source>
        <translation>%1 ohne konsistente Umlaufrichtung (eine nicht orientierbare Oberfläche)</translation>
    </message>
    <message>
        <source>flipped %1 to make the winding consistent</source>
        <translation>%1 umgedreht, um die Umlaufrichtung konsistent zu machen</translation>
    </message>
    <message>
        <source>split %1 where surfaces touch only at that point</source>
        <translation>%1 aufgeteilt, an denen sich Oberflächen nur in diesem einen Punkt berühren</translation>
    </message>
    <message>
        <source>removed %1 no face uses</source>
        <translation>%1 ohne zugehörige Fläche entfernt</translation>
    </message>
</context>
<context>
    <name>phonglab::MeshText</name>
    <message>
        <source>triangle</source>
        <translation>Dreieck</translation>
    </message>
    <message>
        <source>triangles</source>
        <translation>Dreiecke</translation>
    </message>
    <message>
        <source>byte</source>
        <translation>Byte</translation>
    </message>
    <message>
        <source>bytes</source>
        <translation>Byte</translation>
    </message>
    <message>
        <source>face</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <source>faces</source>
        <translation>Flächen</translation>
    </message>
    <message>
        <source>degenerate face</source>
        <translation>entartete Fläche</translation>
    </message>
    <message>
        <source>degenerate faces</source>
        <translation>entartete Flächen</translation>
    </message>
    <message>
        <source>face corner</source>
        <translation>Flächenecke</translation>
    </message>
    <message>
        <source>face corners</source>
        <translation>Flächenecken</translation>
    </message>
    <message>
        <source>non-manifold edge</source>
        <translation>nicht-mannigfaltige Kante</translation>
    </message>
    <message>
        <source>non-manifold edges</source>
        <translation>nicht-mannigfaltige Kanten</translation>
    </message>
    <message>
        <source>edge</source>
        <translation>Kante</translation>
    </message>
    <message>
        <source>edges</source>
        <translation>Kanten</translation>
    </message>
    <message>
        <source>vertex</source>
        <translation>Vertex</translation>
    </message>
    <message>
        <source>vertices</source>
        <translation>Vertices</translation>
    </message>
    <message>
        <source>unreadable line</source>
        <translation>unlesbare Zeile</translation>
    </message>
    <message>
        <source>unreadable lines</source>
        <translation>unlesbare Zeilen</translation>
    </message>
    <message>
        <source>free-form curve or surface statement</source>
        <translation>Anweisung für eine Freiformkurve oder -fläche</translation>
    </message>
    <message>
        <source>free-form curve and surface statements</source>
        <translation>Anweisungen für Freiformkurven und -flächen</translation>
    </message>
    <message>
        <source>face corner refers</source>
        <translation>Flächenecke verweist</translation>
    </message>
    <message>
        <source>face corners refer</source>
        <translation>Flächenecken verweisen</translation>
    </message>
    <message>
        <source>face line</source>
        <translation>Flächenzeile</translation>
    </message>
    <message>
        <source>face lines</source>
        <translation>Flächenzeilen</translation>
    </message>
    <message>
        <source>message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <source>messages</source>
        <translation>Meldungen</translation>
    </message>
    <message>
        <source>facet normal is</source>
        <translation>Facettennormale ist</translation>
    </message>
    <message>
        <source>facet normals are</source>
        <translation>Facettennormalen sind</translation>
    </message>
</context>
<context>
    <name>phonglab::NearestSpelling</name>
    <message>
        <source> (did you mean &apos;%1&apos;?)</source>
        <translation> (gemeint ist wohl &apos;%1&apos;)</translation>
    </message>
    <message>
        <source>unknown option &apos;%1&apos;</source>
        <translation>unbekannte Option &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos;</source>
        <translation>unbekannter Befehl &apos;%1&apos;</translation>
    </message>
</context>
<context>
    <name>phonglab::NormalStudyOutput</name>
    <message>
        <source>%1: cannot write: %2</source>
        <translation>%1: Schreiben nicht möglich: %2</translation>
    </message>
</context>
<context>
    <name>phonglab::NormalsEditor</name>
    <message>
        <source>Normals</source>
        <translation>Normalen</translation>
    </message>
    <message>
        <source>Crease</source>
        <translation>Knickwinkel</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>Verfahren</translation>
    </message>
</context>
<context>
    <name>phonglab::ObjReader</name>
    <message>
        <source>no vertices or faces found (not an OBJ file?)</source>
        <translation>keine Vertices oder Flächen gefunden (keine OBJ-Datei?)</translation>
    </message>
    <message>
        <source>the file has vertices but no faces</source>
        <translation>die Datei hat Vertices, aber keine Flächen</translation>
    </message>
    <message>
        <source>skipped %1 (first at line %2: &quot;%3&quot;)</source>
        <translation>%1 übersprungen (erstmals in Zeile %2: &quot;%3&quot;)</translation>
    </message>
    <message>
        <source>the last line is incomplete (the file looks truncated)</source>
        <translation>die letzte Zeile ist unvollständig (die Datei scheint abgeschnitten)</translation>
    </message>
    <message>
        <source>ignored %1 (only polygons are read)</source>
        <translation>%1 ignoriert (nur Polygone werden gelesen)</translation>
    </message>
    <message>
        <source>%1 to normals the file does not have; they get computed normals</source>
        <translation>%1 auf Normalen, die in der Datei fehlen; sie erhalten berechnete Normalen</translation>
    </message>
</context>
<context>
    <name>phonglab::ObjectDock</name>
    <message>
        <source>scale must not be zero: the object would collapse to a plane</source>
        <translation>Skalierung darf nicht null sein: Das Objekt würde zu einer Ebene zusammenfallen</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <source>Translate</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <source>Rotate (°)</source>
        <translation>Drehen (°)</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Skalieren</translation>
    </message>
</context>
<context>
    <name>phonglab::ObjectEditDock</name>
    <message>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
</context>
<context>
    <name>phonglab::ObjectFit</name>
    <message>
        <source>no per-object rows: nothing to fit object by object</source>
        <translation>keine Zeilen pro Objekt: nichts Objekt für Objekt anzupassen</translation>
    </message>
    <message>
        <source>no combination of the objects&apos; rows meets %1</source>
        <translation>keine Kombination der Zeilen der Objekte erfüllt %1</translation>
    </message>
    <message>
        <source>nothing meets %1 for %2</source>
        <translation>nichts erfüllt %1 für %2</translation>
    </message>
    <message>
        <source> against %1 ms at full-detail Phong</source>
        <translation> gegenüber %1 ms mit Phong in voller Detailstufe</translation>
    </message>
    <message>
        <source>; %1 limits the saving (its fastest, %2 at %3, errs %4/255)</source>
        <translation>; %1 begrenzt die Ersparnis (seine schnellste Variante, %2 in Detailstufe %3, weicht um %4/255 ab)</translation>
    </message>
    <message>
        <source>; every object at its fastest</source>
        <translation>; jedes Objekt in seiner schnellsten Variante</translation>
    </message>
</context>
<context>
    <name>phonglab::OffPrecheck</name>
    <message>
        <source>the binary OFF file ends after %1 of %2 faces (truncated?)</source>
        <translation>die binäre OFF-Datei endet nach %1 von %2 Flächen (abgeschnitten?)</translation>
    </message>
    <message>
        <source>binary OFF face %1 (byte %2) declares %3 corners, more than the %4 bytes left can hold (corrupt?)</source>
        <translation>binäre OFF-Fläche %1 (Byte %2) gibt %3 Ecken an, mehr als die verbleibenden %4 Byte fassen können (beschädigt?)</translation>
    </message>
    <message>
        <source>the binary OFF file ends before its counts</source>
        <translation>die binäre OFF-Datei endet vor der Angabe der Anzahlen</translation>
    </message>
    <message>
        <source>binary %1 files (with colours or texture coordinates) are not supported; save it as ascii OFF or as PLY</source>
        <translation>binäre %1-Dateien (mit Farben oder Texturkoordinaten) werden nicht unterstützt; als ASCII-OFF oder als PLY speichern</translation>
    </message>
    <message>
        <source>the binary OFF header declares %1 vertices and %2 faces, which need at least %3 bytes, but the file has %4 (truncated or corrupt)</source>
        <translation>der binäre OFF-Header gibt %1 Vertices und %2 Flächen an, die mindestens %3 Byte benötigen, aber die Datei hat %4 (abgeschnitten oder beschädigt)</translation>
    </message>
    <message>
        <source>the OFF file has no faces</source>
        <translation>die OFF-Datei hat keine Flächen</translation>
    </message>
    <message>
        <source>not an OFF file (it does not start with an OFF header)</source>
        <translation>keine OFF-Datei (sie beginnt nicht mit einem OFF-Header)</translation>
    </message>
    <message>
        <source>4D and nD OFF files are not supported</source>
        <translation>4D- und nD-OFF-Dateien werden nicht unterstützt</translation>
    </message>
    <message>
        <source>line %1: expected the vertex, face and edge counts, found %2</source>
        <translation>Zeile %1: Anzahl der Vertices, Flächen und Kanten erwartet, gefunden: %2</translation>
    </message>
    <message>
        <source>line %1: unexpected text after the counts</source>
        <translation>Zeile %1: unerwarteter Text nach den Anzahlen</translation>
    </message>
    <message>
        <source>the OFF header declares %1 vertices and %2 faces, which need at least %3 bytes, but the file has %4 (truncated or corrupt)</source>
        <translation>der OFF-Header gibt %1 Vertices und %2 Flächen an, die mindestens %3 Byte benötigen, aber die Datei hat %4 (abgeschnitten oder beschädigt)</translation>
    </message>
    <message>
        <source>the file ends after %1 of %2 vertices (truncated?)</source>
        <translation>die Datei endet nach %1 von %2 Vertices (abgeschnitten?)</translation>
    </message>
    <message>
        <source>expected a number, found %1</source>
        <translation>Zahl erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>the file ends after %1 of %2 faces (truncated?)</source>
        <translation>die Datei endet nach %1 von %2 Flächen (abgeschnitten?)</translation>
    </message>
    <message>
        <source>expected the corner count of face %1, found %2</source>
        <translation>Eckenzahl von Fläche %1 erwartet, gefunden: %2</translation>
    </message>
    <message>
        <source>face %1 has %2 corners but only %3 indices</source>
        <translation>Fläche %1 hat %2 Ecken, aber nur %3 Indizes</translation>
    </message>
    <message>
        <source>a vertex index</source>
        <translation>ein Vertex-Index</translation>
    </message>
    <message>
        <source>ignored the values after the vertex indices on %1 (face colours need a COFF header)</source>
        <translation>Werte nach den Vertex-Indizes in %1 ignoriert (Flächenfarben erfordern einen COFF-Header)</translation>
    </message>
    <message>
        <source>ignored the text after the last face (from line %1)</source>
        <translation>Text nach der letzten Fläche ignoriert (ab Zeile %1)</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>eine Zahl</translation>
    </message>
    <message>
        <source>vertex %1 needs %2 numbers, found %3</source>
        <translation>Vertex %1 braucht %2 Zahlen, gefunden: %3</translation>
    </message>
    <message>
        <source>expected %1, found %2</source>
        <translation>%1 erwartet, gefunden: %2</translation>
    </message>
</context>
<context>
    <name>phonglab::OffscreenRenderer</name>
    <message>
        <source>no OpenGL context could be created without a display server: %1. PhongLab renders through EGL there (Mesa: packages libegl1 and libegl-mesa0), or under an X server (`xvfb-run -a phonglab ...`)</source>
        <translation>ohne Display-Server konnte kein OpenGL-Kontext erstellt werden: %1. PhongLab rendert dort über EGL (Mesa: Pakete libegl1 und libegl-mesa0) oder unter einem X-Server (`xvfb-run -a phonglab ...`)</translation>
    </message>
    <message>
        <source>no OpenGL context could be created on Qt&apos;s &apos;%1&apos; platform%2; QT_QPA_PLATFORM=phonglab-headless renders through EGL without a display server</source>
        <translation>auf der Qt-Plattform &apos;%1&apos;%2 konnte kein OpenGL-Kontext erstellt werden; mit QT_QPA_PLATFORM=phonglab-headless wird über EGL ohne Display-Server gerendert</translation>
    </message>
    <message>
        <source>OpenGL 3.3 is required, the driver offers %1.%2</source>
        <translation>OpenGL 3.3 ist erforderlich, der Treiber bietet %1.%2</translation>
    </message>
    <message>
        <source>the OpenGL context could not be made current on an offscreen surface</source>
        <translation>der OpenGL-Kontext konnte auf einer Offscreen-Oberfläche nicht als aktueller Kontext gesetzt werden</translation>
    </message>
</context>
<context>
    <name>phonglab::OmPrecheck</name>
    <message>
        <source>a %1 chunk with %2 components per element, where the reader expects %3</source>
        <translation>ein Chunk %1 mit %2 Komponenten pro Element, wo das Einleseprogramm %3 erwartet</translation>
    </message>
    <message>
        <source>a %1 chunk with a number size the reader does not know</source>
        <translation>ein Chunk %1 mit einer Zahlengröße, die das Einleseprogramm nicht kennt</translation>
    </message>
    <message>
        <source>the file ends inside a custom property chunk</source>
        <translation>die Datei endet innerhalb eines Chunks mit einer benutzerdefinierten Eigenschaft</translation>
    </message>
    <message>
        <source>the file ends after %1 of %2 faces (truncated?)</source>
        <translation>die Datei endet nach %1 von %2 Flächen (abgeschnitten?)</translation>
    </message>
    <message>
        <source>face %1 of %2 runs past the end of the file (truncated?)</source>
        <translation>Fläche %1 von %2 reicht über das Dateiende hinaus (abgeschnitten?)</translation>
    </message>
    <message>
        <source>a chunk for an unknown kind of element (%1)</source>
        <translation>ein Chunk für eine unbekannte Elementart (%1)</translation>
    </message>
    <message>
        <source>the file ends after %1 chunks, before the end marker OpenMesh writes (truncated?)</source>
        <translation>die Datei endet nach %1 Chunks, vor der Endmarkierung, die OpenMesh schreibt (abgeschnitten?)</translation>
    </message>
    <message>
        <source>chunk %1 (byte %2): the file ends inside its property name</source>
        <translation>Chunk %1 (Byte %2): die Datei endet innerhalb seines Eigenschaftsnamens</translation>
    </message>
    <message>
        <source>chunk %1 (byte %2, %3) needs %4 bytes, but only %5 are left (truncated or corrupt)</source>
        <translation>Chunk %1 (Byte %2, %3) benötigt %4 Byte, aber nur %5 sind übrig (abgeschnitten oder beschädigt)</translation>
    </message>
    <message>
        <source>the file ends inside the OpenMesh header</source>
        <translation>die Datei endet innerhalb des OpenMesh-Headers</translation>
    </message>
    <message>
        <source>the OpenMesh header declares %1 vertices and %2 faces, which need at least %3 bytes, but the file has %4 (truncated or corrupt)</source>
        <translation>der OpenMesh-Header gibt %1 Vertices und %2 Flächen an, die mindestens %3 Byte benötigen, aber die Datei hat %4 (abgeschnitten oder beschädigt)</translation>
    </message>
    <message>
        <source>the OpenMesh file has no faces</source>
        <translation>die OpenMesh-Datei hat keine Flächen</translation>
    </message>
    <message>
        <source>%1 bytes after the end marker were ignored</source>
        <translation>%1 Byte nach der Endmarkierung wurden ignoriert</translation>
    </message>
</context>
<context>
    <name>phonglab::OpenMeshReader</name>
    <message>
        <source>the file ends before its end marker (truncated?)</source>
        <translation>die Datei endet vor ihrer Endmarkierung (abgeschnitten?)</translation>
    </message>
    <message>
        <source>cannot open the file</source>
        <translation>die Datei kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>cannot write a cleaned copy of the OFF file to the temporary folder</source>
        <translation>eine bereinigte Kopie der OFF-Datei kann nicht in den temporären Ordner geschrieben werden</translation>
    </message>
    <message>
        <source>out of memory while reading the file</source>
        <translation>Arbeitsspeicher beim Lesen der Datei erschöpft</translation>
    </message>
    <message>
        <source>the reader failed: %1</source>
        <translation>das Einlesen ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>the reader failed</source>
        <translation>das Einlesen ist fehlgeschlagen</translation>
    </message>
    <message>
        <source>OpenMesh could not read the file</source>
        <translation>OpenMesh konnte die Datei nicht lesen</translation>
    </message>
    <message>
        <source>OpenMesh could not read the file: %1</source>
        <translation>OpenMesh konnte die Datei nicht lesen: %1</translation>
    </message>
    <message>
        <source>read %1 of the %2 the header declares</source>
        <translation>%1 von %2 gelesen (laut Header)</translation>
    </message>
    <message>
        <source>dropped %1 with two corners at the same position</source>
        <translation>%1 mit zwei Ecken an derselben Position verworfen</translation>
    </message>
    <message>
        <source>no faces were read</source>
        <translation>es wurden keine Flächen gelesen</translation>
    </message>
</context>
<context>
    <name>phonglab::PageCapture</name>
    <message>
        <source>not JSON at byte %1: %2</source>
        <translation>kein JSON bei Byte %1: %2</translation>
    </message>
    <message>
        <source>not a page capture of format 1 (key &quot;format&quot;)</source>
        <translation>keine Seitenaufzeichnung im Format 1 (Schlüssel &quot;format&quot;)</translation>
    </message>
    <message>
        <source>key &quot;pixels&quot;: %1 bytes for a canvas of %2x%3</source>
        <translation>Schlüssel &quot;pixels&quot;: %1 Bytes für eine Zeichenfläche von %2x%3</translation>
    </message>
    <message>
        <source>key &quot;draws&quot;: %1 clears and draws in one frame, more than PhongLab checks (%2)</source>
        <translation>Schlüssel &quot;draws&quot;: %1 Löschungen und Zeichenaufrufe in einem Bild, mehr als PhongLab prüft (%2)</translation>
    </message>
    <message>
        <source>key &quot;draws&quot;: %1 vertices in one frame, more than PhongLab checks (%2)</source>
        <translation>Schlüssel &quot;draws&quot;: %1 Vertices in einem Bild, mehr als PhongLab prüft (%2)</translation>
    </message>
</context>
<context>
    <name>phonglab::PageCheck</name>
    <message>
        <source>%1: cannot make the folder</source>
        <translation>%1: Ordner kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>the page drew nothing to its canvas</source>
        <translation>die Seite hat nichts auf ihre Zeichenfläche gezeichnet</translation>
    </message>
    <message>
        <source>the page drew no program that lights: the course scene is not checked</source>
        <translation>die Seite hat kein Programm gezeichnet, das beleuchtet: die Kursszene wird nicht geprüft</translation>
    </message>
    <message>
        <source>the course scene is checked with program %1 as the page compiled it: %2 and %3</source>
        <translation>die Kursszene wird mit Programm %1 geprüft, wie die Seite es kompiliert hat: %2 und %3</translation>
    </message>
    <message>
        <source>%1: cannot write</source>
        <translation>%1: nicht schreibbar</translation>
    </message>
</context>
<context>
    <name>phonglab::PageCheckOutput</name>
    <message>
        <source>page: not run: %1</source>
        <translation>Seite: nicht ausgeführt: %1</translation>
    </message>
    <message>
        <source>page: %1, WebGL %2, frame %3 of a %4x%5 canvas%6</source>
        <translation>Seite: %1, WebGL %2, Bild %3 einer Zeichenfläche von %4x%5%6</translation>
    </message>
    <message>
        <source>page step &apos;%1&apos;: %2</source>
        <translation>Seitenschritt &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>refused (the page gets no network): %1</source>
        <translation>abgewiesen (die Seite bekommt kein Netzwerk): %1</translation>
    </message>
    <message>
        <source>page error: %1</source>
        <translation>Fehler der Seite: %1</translation>
    </message>
    <message>
        <source>fidelity: PhongLab draws the page&apos;s frame as the browser did (largest difference %1 outside edges)</source>
        <translation>Treue: PhongLab zeichnet das Bild der Seite so, wie der Browser es tat (größte Abweichung %1 außerhalb von Kanten)</translation>
    </message>
    <message>
        <source>fidelity: PhongLab does not draw the page&apos;s frame as the browser did (largest difference %1 outside edges): what follows may be PhongLab&apos;s mistake, not the student&apos;s</source>
        <translation>Treue: PhongLab zeichnet das Bild der Seite nicht so, wie der Browser es tat (größte Abweichung %1 außerhalb von Kanten): was folgt, kann PhongLabs Fehler sein, nicht der des Studierenden</translation>
    </message>
    <message>
        <source>fidelity: not checked: %1</source>
        <translation>Treue: nicht geprüft: %1</translation>
    </message>
    <message>
        <source>not drawn again: %1</source>
        <translation>nicht erneut gezeichnet: %1</translation>
    </message>
    <message>
        <source>javascript: %1</source>
        <translation>JavaScript: %1</translation>
    </message>
    <message>
        <source>javascript ok: %1</source>
        <translation>JavaScript in Ordnung: %1</translation>
    </message>
    <message>
        <source>course mesh not read: %1</source>
        <translation>Kurs-Mesh nicht gelesen: %1</translation>
    </message>
    <message>
        <source>own scene: %1</source>
        <translation>eigene Szene: %1</translation>
    </message>
    <message>
        <source>own scene: not checked: %1</source>
        <translation>eigene Szene: nicht geprüft: %1</translation>
    </message>
</context>
<context>
    <name>phonglab::PageMatrices</name>
    <message>
        <source>the model matrix</source>
        <translation>der Modellmatrix</translation>
    </message>
    <message>
        <source>the model-view</source>
        <translation>der Model-View-Matrix</translation>
    </message>
    <message>
        <source>%1 is the inverse transpose of %2</source>
        <translation>%1 ist die inverse Transponierte %2</translation>
    </message>
    <message>
        <source>%1 is the transpose of %2, not its inverse transpose: where it rotates, the normals turn the other way</source>
        <translation>%1 ist die Transponierte %2, nicht ihre inverse Transponierte: wo sie dreht, drehen sich die Normalen in die andere Richtung</translation>
    </message>
    <message>
        <source>%1 is the inverse of %2, not its inverse transpose</source>
        <translation>%1 ist die Inverse %2, nicht ihre inverse Transponierte</translation>
    </message>
    <message>
        <source>%1 is %2 itself, not its inverse transpose: under a scaling that is not uniform the normals tilt</source>
        <translation>%1 ist die Matrix selbst (%2), nicht ihre inverse Transponierte: unter einer ungleichmäßigen Skalierung kippen die Normalen</translation>
    </message>
    <message>
        <source>%1 is not the inverse transpose of %2 sent</source>
        <translation>%1 ist nicht die inverse Transponierte %2, die gesendet wird</translation>
    </message>
    <message>
        <source>%1 is the inverse transpose of the model matrix alone: the view is left out, so the normals are in world coordinates and the rest in camera coordinates</source>
        <translation>%1 ist die inverse Transponierte der Modellmatrix allein: die View-Matrix fehlt, die Normalen sind also in Weltkoordinaten und der Rest in Kamerakoordinaten</translation>
    </message>
    <message>
        <source>%1 is not the view matrix times the model matrix the page sends beside it</source>
        <translation>%1 ist nicht View-Matrix mal Modellmatrix, die die Seite daneben sendet</translation>
    </message>
    <message>
        <source>%1 is not the projection times the model-view the page sends beside it</source>
        <translation>%1 ist nicht Projektion mal Model-View, die die Seite daneben sendet</translation>
    </message>
    <message>
        <source>%1 is sent with w = 0: a direction, not a place; right only where the shader lights from a direction</source>
        <translation>%1 wird mit w = 0 gesendet: eine Richtung, kein Ort; richtig nur, wo der Shader aus einer Richtung beleuchtet</translation>
    </message>
    <message>
        <source>%1 is not %2 · %3, which the page sends beside it</source>
        <translation>%1 ist nicht %2 · %3, die die Seite daneben sendet</translation>
    </message>
</context>
<context>
    <name>phonglab::PageNormals</name>
    <message>
        <source>%1 is drawn without normals: the shader&apos;s normal input gets no buffer</source>
        <translation>%1 wird ohne Normalen gezeichnet: der Normalen-Eingang des Shaders bekommt keinen Puffer</translation>
    </message>
    <message>
        <source>%1: Blender&apos;s normals, exactly</source>
        <translation>%1: genau die Normalen aus Blender</translation>
    </message>
    <message>
        <source>%1: the faces&apos; normals instead of Blender&apos;s (%2 % of the vertices): the mesh looks faceted</source>
        <translation>%1: die Flächennormalen statt der aus Blender (%2 % der Vertices): das Mesh wirkt facettiert</translation>
    </message>
    <message>
        <source>%1: Blender&apos;s directions, but not of length 1 (%2 % of the vertices)</source>
        <translation>%1: die Richtungen aus Blender, aber nicht der Länge 1 (%2 % der Vertices)</translation>
    </message>
    <message>
        <source>%1: the positions sent as normals (%2 % of the vertices)</source>
        <translation>%1: die Positionen als Normalen gesendet (%2 % der Vertices)</translation>
    </message>
    <message>
        <source>%1: normals that are neither Blender&apos;s nor the faces&apos; (%2 % of the vertices)</source>
        <translation>%1: Normalen, die weder die aus Blender noch die der Flächen sind (%2 % der Vertices)</translation>
    </message>
    <message>
        <source>%1 is not drawn in the captured frame (its positions are in no draw&apos;s buffer)</source>
        <translation>%1 wird im aufgezeichneten Bild nicht gezeichnet (seine Positionen stehen in keinem Puffer eines Zeichenaufrufs)</translation>
    </message>
</context>
<context>
    <name>phonglab::PageReplay</name>
    <message>
        <source>%1 samples a texture, which is not captured</source>
        <translation>%1 tastet eine Textur ab, die nicht aufgezeichnet wird</translation>
    </message>
    <message>
        <source>uniform %1 has a type PhongLab does not set again</source>
        <translation>Uniform %1 hat einen Typ, den PhongLab nicht erneut setzt</translation>
    </message>
    <message>
        <source>program %1 does not build here: %2</source>
        <translation>Programm %1 lässt sich hier nicht bauen: %2</translation>
    </message>
    <message>
        <source>program %1 is not in the capture</source>
        <translation>Programm %1 fehlt in der Aufzeichnung</translation>
    </message>
    <message>
        <source>the page drew nothing to its canvas</source>
        <translation>die Seite hat nichts auf ihre Zeichenfläche gezeichnet</translation>
    </message>
    <message>
        <source>no %1x%2 framebuffer here</source>
        <translation>hier kein Framebuffer von %1x%2</translation>
    </message>
</context>
<context>
    <name>phonglab::PageRun</name>
    <message>
        <source>larger than 64 MB</source>
        <translation>größer als 64 MB</translation>
    </message>
    <message>
        <source>running the page needs Chromium, which is not installed (sudo apt install chromium; scripts/setup.sh installs it); the shaders are still read from the files</source>
        <translation>um die Seite auszuführen, braucht es Chromium, das nicht installiert ist (sudo apt install chromium; scripts/setup.sh installiert es); die Shader werden weiterhin aus den Dateien gelesen</translation>
    </message>
    <message>
        <source>%1: no such folder</source>
        <translation>%1: kein solcher Ordner</translation>
    </message>
    <message>
        <source>%1: no page %2 in the project</source>
        <translation>%1: keine Seite %2 im Projekt</translation>
    </message>
    <message>
        <source>%1: no HTML page in the project</source>
        <translation>%1: keine HTML-Seite im Projekt</translation>
    </message>
    <message>
        <source>%1: which page? it has %2 (choose one with --page-file)</source>
        <translation>%1: welche Seite? Es gibt %2 (eine mit --page-file wählen)</translation>
    </message>
    <message>
        <source>cannot make a folder for the browser&apos;s profile</source>
        <translation>kein Ordner für das Profil des Browsers möglich</translation>
    </message>
    <message>
        <source>the capture failed: %1</source>
        <translation>die Aufzeichnung ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>the page&apos;s document was replaced before it could be captured</source>
        <translation>das Dokument der Seite wurde ersetzt, bevor es aufgezeichnet werden konnte</translation>
    </message>
    <message>
        <source>the page %1 could not be opened: %2</source>
        <translation>die Seite %1 ließ sich nicht öffnen: %2</translation>
    </message>
</context>
<context>
    <name>phonglab::PageRunDialog</name>
    <message>
        <source>Run the Page</source>
        <translation>Seite ausführen</translation>
    </message>
    <message>
        <source>the browser</source>
        <translation>im Browser</translation>
    </message>
    <message>
        <source>PhongLab, drawn again</source>
        <translation>PhongLab, erneut gezeichnet</translation>
    </message>
    <message>
        <source>difference</source>
        <translation>Differenz</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Running %1 in Chromium (headless, WebGL on SwiftShader, no network)…</source>
        <translation>%1 läuft in Chromium (headless, WebGL auf SwiftShader, kein Netzwerk)…</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>Frame %1 of %2, as the browser drew it.</source>
        <translation>Bild %1 von %2, wie der Browser es gezeichnet hat.</translation>
    </message>
    <message>
        <source>The page was not run: %1</source>
        <translation>Die Seite wurde nicht ausgeführt: %1</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Wird abgebrochen…</translation>
    </message>
</context>
<context>
    <name>phonglab::PageScene</name>
    <message>
        <source>the projection sent is not a symmetric perspective</source>
        <translation>die gesendete Projektion ist keine symmetrische Perspektive</translation>
    </message>
    <message>
        <source>the projection&apos;s aspect (%1) is not the canvas&apos;s (%2)</source>
        <translation>das Seitenverhältnis der Projektion (%1) ist nicht das der Zeichenfläche (%2)</translation>
    </message>
    <message>
        <source>the projection sent has no near and far planes in front</source>
        <translation>die gesendete Projektion hat keine Near- und Far-Ebene vor der Kamera</translation>
    </message>
    <message>
        <source>a draw that is not one list of triangles</source>
        <translation>ein Zeichenaufruf, der keine einfache Dreiecksliste ist</translation>
    </message>
    <message>
        <source>no vertex input is the position</source>
        <translation>kein Vertex-Eingang ist die Position</translation>
    </message>
    <message>
        <source>drawn without normals</source>
        <translation>ohne Normalen gezeichnet</translation>
    </message>
    <message>
        <source>a draw past its buffers</source>
        <translation>ein Zeichenaufruf über seine Puffer hinaus</translation>
    </message>
    <message>
        <source>its triangles make no mesh</source>
        <translation>seine Dreiecke ergeben kein Mesh</translation>
    </message>
    <message>
        <source>the specular term has no shininess sent</source>
        <translation>der spiegelnde Term hat keine gesendete Glanzzahl</translation>
    </message>
    <message>
        <source>light %1 has no position sent</source>
        <translation>Licht %1 hat keine gesendete Position</translation>
    </message>
    <message>
        <source>no light is sent</source>
        <translation>es wird kein Licht gesendet</translation>
    </message>
    <message>
        <source>the page drew no program that lights</source>
        <translation>die Seite hat kein Programm gezeichnet, das beleuchtet</translation>
    </message>
    <message>
        <source>uniform %1 changes the image but means nothing PhongLab knows</source>
        <translation>Uniform %1 verändert das Bild, bedeutet aber nichts, was PhongLab kennt</translation>
    </message>
    <message>
        <source>a draw&apos;s viewport is not the whole canvas</source>
        <translation>der Viewport eines Zeichenaufrufs ist nicht die ganze Zeichenfläche</translation>
    </message>
    <message>
        <source>the page sends no projection of its own (only a product of its matrices)</source>
        <translation>die Seite sendet keine eigene Projektion (nur ein Produkt ihrer Matrizen)</translation>
    </message>
    <message>
        <source>the page sends no model-view, nor a view and a model</source>
        <translation>die Seite sendet keine Model-View, auch keine View- und Modellmatrix</translation>
    </message>
    <message>
        <source>two draws send different lights</source>
        <translation>zwei Zeichenaufrufe senden verschiedene Lichter</translation>
    </message>
    <message>
        <source>the page drew nothing to its canvas</source>
        <translation>die Seite hat nichts auf ihre Zeichenfläche gezeichnet</translation>
    </message>
    <message>
        <source>light %1 is a direction (w = 0): the exact image here lights from points</source>
        <translation>Licht %1 ist eine Richtung (w = 0): das exakte Bild hier beleuchtet von Punkten aus</translation>
    </message>
</context>
<context>
    <name>phonglab::PathBench</name>
    <message>
        <source>the path bench has no OpenGL context</source>
        <translation>der Pfad-Benchmark hat keinen OpenGL-Kontext</translation>
    </message>
    <message>
        <source>%1, frame %2: no reference: %3</source>
        <translation>%1, Frame %2: keine Referenz: %3</translation>
    </message>
</context>
<context>
    <name>phonglab::PathChart</name>
    <message>
        <source>%1 — %2: %3 of %4 frames over budget (%5)</source>
        <translation>%1 — %2: %3 von %4 Frames über dem Budget (%5)</translation>
    </message>
    <message>
        <source>max error (auto detail, unseen lights left out)</source>
        <translation>max. Fehler (automatische Detailstufe, unsichtbare Lichtquellen weggelassen)</translation>
    </message>
    <message>
        <source>frame ms, auto detail</source>
        <translation>Frame-ms, automatische Detailstufe</translation>
    </message>
    <message>
        <source>frame ms, full detail</source>
        <translation>Frame-ms, volle Detailstufe</translation>
    </message>
    <message>
        <source>frame along the path</source>
        <translation>Frame entlang des Pfads</translation>
    </message>
    <message>
        <source>max error, 8-bit steps</source>
        <translation>max. Fehler, 8-Bit-Stufen</translation>
    </message>
    <message>
        <source>ms per frame</source>
        <translation>ms pro Frame</translation>
    </message>
    <message>
        <source>no camera path to chart</source>
        <translation>kein Kamerapfad für ein Diagramm</translation>
    </message>
    <message>
        <source>PhongLab camera paths: error and time per frame</source>
        <translation>PhongLab-Kamerapfade: Fehler und Zeit pro Frame</translation>
    </message>
</context>
<context>
    <name>phonglab::PerformanceDock</name>
    <message>
        <source>Performance</source>
        <translation>Leistung</translation>
    </message>
    <message>
        <source>Frame: -</source>
        <translation>Frame: -</translation>
    </message>
    <message>
        <source>Draw time per frame (first OpenGL call to glFinish), the mean of the last second&apos;s frames, and the triangles drawn.</source>
        <translation>Zeichenzeit pro Frame (vom ersten OpenGL-Aufruf bis glFinish), der Mittelwert über die Frames der letzten Sekunde und die gezeichneten Dreiecke.</translation>
    </message>
    <message>
        <source>Error budget:</source>
        <translation>Fehlerbudget:</translation>
    </message>
    <message>
        <source>max error (8-bit steps)</source>
        <translation>max. Fehler (8-Bit-Stufen)</translation>
    </message>
    <message>
        <source>PSNR at least (dB)</source>
        <translation>PSNR mindestens (dB)</translation>
    </message>
    <message>
        <source>Measured against the exact CPU reference, more than 2 px from silhouettes.</source>
        <translation>Gemessen an der exakten CPU-Referenz, mehr als 2 px von Silhouetten entfernt.</translation>
    </message>
    <message>
        <source>Model only what the view needs</source>
        <translation>Nur modellieren, was die Ansicht braucht</translation>
    </message>
    <message>
        <source>Every object at &quot;detail&quot;: &quot;auto&quot;: drawn at the coarsest level its size on screen allows, and without the lights it cannot show, each within a quarter of the budget. The levels are built in the background the first time.</source>
        <translation>Jedes Objekt mit &quot;detail&quot;: &quot;auto&quot;: gezeichnet in der gröbsten Detailstufe, die seine Größe auf dem Bildschirm erlaubt, und ohne die Lichtquellen, die es nicht zeigen kann, jeweils innerhalb eines Viertels des Budgets. Die Detailstufen werden beim ersten Mal im Hintergrund gebaut.</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Messen</translation>
    </message>
    <message>
        <source>Time every shipped method at every detail level for this view and these lights and compare each with the exact answer.</source>
        <translation>Jedes mitgelieferte Schattierungsverfahren in jeder Detailstufe für diese Ansicht und diese Lichtquellen messen und jeweils mit dem exakten Bild vergleichen.</translation>
    </message>
    <message>
        <source>Fit to budget</source>
        <translation>An Budget anpassen</translation>
    </message>
    <message>
        <source>Measure, then show the cheapest method and coarsest detail within the budget.</source>
        <translation>Messen und dann das günstigste Schattierungsverfahren und die gröbste Detailstufe innerhalb des Budgets zeigen.</translation>
    </message>
    <message>
        <source>Full detail</source>
        <translation>Volle Detailstufe</translation>
    </message>
    <message>
        <source>Back to every object&apos;s full mesh and the shading used before the fit.</source>
        <translation>Zurück zum vollständigen Mesh jedes Objekts und zum Schattierungsverfahren von vor der Anpassung.</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Measure to see frame time against error for every method and detail level.</source>
        <translation>Messen, um Framezeit und Fehler für jedes Schattierungsverfahren und jede Detailstufe zu vergleichen.</translation>
    </message>
    <message>
        <source> dB</source>
        <translation> dB</translation>
    </message>
    <message>
        <source> /255</source>
        <translation> /255</translation>
    </message>
    <message>
        <source>Cannot measure: %1</source>
        <translation>Messung nicht möglich: %1</translation>
    </message>
    <message>
        <source>Measuring %1 × %2 px with the scene&apos;s lights…</source>
        <translation>Messung bei %1 × %2 px mit den Lichtquellen der Szene…</translation>
    </message>
    <message>
        <source>Measurement cancelled.</source>
        <translation>Messung abgebrochen.</translation>
    </message>
    <message>
        <source>Measurement failed: %1</source>
        <translation>Messung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Within %1: %2</source>
        <translation>Innerhalb von %1: %2</translation>
    </message>
    <message>
        <source>Fitted to %1: %2 shading at detail %3, %4 triangles, %5 ms per frame (measured offscreen, without multisampling).</source>
        <translation>An %1 angepasst: Schattierungsverfahren %2 in Detailstufe %3, %4 Dreiecke, %5 ms pro Frame (offscreen gemessen, ohne Multisampling).</translation>
    </message>
    <message>
        <source> Saved against full-detail Phong: %1 triangles (%2 %) and %3 ms (%4 → %5 ms).</source>
        <translation> Ersparnis gegenüber Phong in voller Detailstufe: %1 Dreiecke (%2 %) und %3 ms (%4 → %5 ms).</translation>
    </message>
    <message>
        <source>Back to full detail with %1 shading.</source>
        <translation>Zurück zur vollen Detailstufe mit dem Schattierungsverfahren %1.</translation>
    </message>
    <message>
        <source>This view: frame time against error</source>
        <translation>Diese Ansicht: Framezeit gegenüber Fehler</translation>
    </message>
    <message>
        <source>Frame: %1 ms · %2 triangles</source>
        <translation>Frame: %1 ms · %2 Dreiecke</translation>
    </message>
</context>
<context>
    <name>phonglab::PixelInspectorDock</name>
    <message>
        <source>Pixel Inspector</source>
        <translation>Pixel-Inspektor</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Kopieren</translation>
    </message>
    <message>
        <source>Copy the values as text</source>
        <translation>Die Werte als Text kopieren</translation>
    </message>
    <message>
        <source>Turn on Inspect (I) and click a pixel, or Ctrl+click one, to see the terms of the equation there.</source>
        <translation>Inspizieren (I) einschalten und ein Pixel anklicken (oder eines mit Ctrl+Klick wählen), um dort die Anteile der Beleuchtungsgleichung zu sehen.</translation>
    </message>
    <message>
        <source>yours</source>
        <translation>eigenes</translation>
    </message>
    <message>
        <source>exact</source>
        <translation>exakt</translation>
    </message>
</context>
<context>
    <name>phonglab::PixelTerms</name>
    <message>
        <source>normals view</source>
        <translation>Normalenansicht</translation>
    </message>
    <message>
        <source>Phong, the slide&apos;s equation (a highlight even where N·L &lt;= 0)</source>
        <translation>Phong, die Gleichung der Folie (ein Glanzlicht auch dort, wo N·L &lt;= 0 ist)</translation>
    </message>
    <message>
        <source>pixel (%1, %2), object %3, %4</source>
        <translation>Pixel (%1, %2), Objekt %3, %4</translation>
    </message>
    <message>
        <source>I exact  %1 -&gt; 8-bit (%2, %3, %4)</source>
        <translation>I exakt  %1 -&gt; 8 Bit (%2, %3, %4)</translation>
    </message>
    <message>
        <source>light %1</source>
        <translation>Licht %1</translation>
    </message>
</context>
<context>
    <name>phonglab::PlyPrecheck</name>
    <message>
        <source>PLY header line %1</source>
        <translation>PLY-Header, Zeile %1</translation>
    </message>
    <message>
        <source>not a PLY file (it does not start with &apos;ply&apos;)</source>
        <translation>keine PLY-Datei (sie beginnt nicht mit &apos;ply&apos;)</translation>
    </message>
    <message>
        <source>: byte 0x%1 at column %2 is not text (a binary body before &apos;end_header&apos;?)</source>
        <translation>: Byte 0x%1 in Spalte %2 ist kein Text (binäre Daten vor &apos;end_header&apos;?)</translation>
    </message>
    <message>
        <source>: &apos;format&apos; without a format</source>
        <translation>: &apos;format&apos; ohne Format</translation>
    </message>
    <message>
        <source>: unknown format %1</source>
        <translation>: unbekanntes Format %1</translation>
    </message>
    <message>
        <source>: a property before any element</source>
        <translation>: property vor dem ersten element</translation>
    </message>
    <message>
        <source>: unknown or unusable list types</source>
        <translation>: unbekannte oder unbrauchbare Listentypen</translation>
    </message>
    <message>
        <source>: unknown property type %1</source>
        <translation>: unbekannter Eigenschaftstyp %1</translation>
    </message>
    <message>
        <source>: words after &apos;end_header&apos;</source>
        <translation>: Wörter nach &apos;end_header&apos;</translation>
    </message>
    <message>
        <source>the PLY header has no &apos;format&apos; line</source>
        <translation>der PLY-Header hat keine &apos;format&apos;-Zeile</translation>
    </message>
    <message>
        <source>: unknown keyword %1</source>
        <translation>: unbekanntes Schlüsselwort %1</translation>
    </message>
    <message>
        <source>the PLY header has no &apos;end_header&apos; line (truncated or not a PLY file)</source>
        <translation>der PLY-Header hat keine &apos;end_header&apos;-Zeile (abgeschnitten oder keine PLY-Datei)</translation>
    </message>
    <message>
        <source>the file ends inside %1 %2 of %3 (truncated?)</source>
        <translation>die Datei endet innerhalb von %1 %2 von %3 (abgeschnitten?)</translation>
    </message>
    <message>
        <source>%1 %2 has a negative list length</source>
        <translation>%1 %2 hat eine negative Listenlänge</translation>
    </message>
    <message>
        <source>ignored %1 after the last element</source>
        <translation>%1 nach dem letzten Element ignoriert</translation>
    </message>
    <message>
        <source>an integer</source>
        <translation>eine ganze Zahl</translation>
    </message>
    <message>
        <source>a list length</source>
        <translation>eine Listenlänge</translation>
    </message>
    <message>
        <source>ignored the text after the last element (from line %1)</source>
        <translation>Text nach dem letzten Element ignoriert (ab Zeile %1)</translation>
    </message>
    <message>
        <source>cannot open the file: %1</source>
        <translation>die Datei kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>the PLY file has no vertex element with x, y and z</source>
        <translation>die PLY-Datei hat kein vertex-Element mit x, y und z</translation>
    </message>
    <message>
        <source>the PLY file has no faces (a point cloud?)</source>
        <translation>die PLY-Datei hat keine Flächen (eine Punktwolke?)</translation>
    </message>
    <message>
        <source>the header declares %1 %2 elements, which need at least %3 bytes, but the file has %4 bytes after the header (truncated or corrupt)</source>
        <translation>der Header gibt %1 %2-Elemente an, die mindestens %3 Byte benötigen, aber die Datei hat nach dem Header %4 Byte (abgeschnitten oder beschädigt)</translation>
    </message>
    <message>
        <source>an ascii PLY file with binary data in it (a NUL byte)</source>
        <translation>eine ASCII-PLY-Datei mit binären Daten darin (ein NUL-Byte)</translation>
    </message>
</context>
<context>
    <name>phonglab::PolygonSoupImporter</name>
    <message>
        <source>dropped %1 whose halfedge loop in the .om file is broken</source>
        <translation>%1 mit unterbrochenem Halbkantenzyklus in der .om-Datei verworfen</translation>
    </message>
    <message>
        <source>the file&apos;s facet normals are all zero or invalid; normals will be computed</source>
        <translation>die Facettennormalen der Datei sind alle null oder ungültig; die Normalen werden berechnet</translation>
    </message>
    <message>
        <source>%1 zero or invalid; those faces get computed normals</source>
        <translation>%1 null oder ungültig; diese Flächen erhalten berechnete Normalen</translation>
    </message>
</context>
<context>
    <name>phonglab::ProgramBuilder</name>
    <message>
        <source>%1 failed without a message from the driver</source>
        <translation>%1 ohne Meldung des Treibers fehlgeschlagen</translation>
    </message>
    <message>
        <source> (GLSL ES 1.00, WebGL 1, has no inverse() or transpose(): write #version 300 es, or pass the normal matrix in as a uniform)</source>
        <translation> (GLSL ES 1.00, WebGL 1, kennt weder inverse() noch transpose(): #version 300 es schreiben oder die Normalenmatrix als Uniform-Variable übergeben)</translation>
    </message>
    <message>
        <source> (this OpenGL driver does not run %1 shaders in a desktop context: it lacks ARB_ES%2_compatibility)</source>
        <translation> (dieser OpenGL-Treiber führt %1-Shader nicht in einem Desktop-Kontext aus: ihm fehlt ARB_ES%2_compatibility)</translation>
    </message>
    <message>
        <source>the vertex shader is %1 and the fragment shader %2: both stages must be written in the same GLSL (give both files)</source>
        <translation>der Vertex-Shader ist %1 und der Fragment-Shader %2: Beide Stufen müssen in derselben GLSL-Version geschrieben sein (beide Dateien angeben)</translation>
    </message>
</context>
<context>
    <name>phonglab::ProgramFindings</name>
    <message>
        <source>uniform %1 (%2) is bound to nothing, so the shader reads zero</source>
        <translation>Uniform %1 (%2) ist nichts zugeordnet, daher liest der Shader null</translation>
    </message>
    <message>
        <source>%1=%2: %3 (%4 shader, line %5)</source>
        <translation>%1=%2: %3 (%4-Shader, Zeile %5)</translation>
    </message>
    <message>
        <source>the shader takes %1 %2 (its light uniforms have room for no more) and the scene has %3 enabled: checked with the first %1 alone</source>
        <translation>der Shader verarbeitet %1 %2 (seine Uniform-Variablen für Lichtquellen bieten keinen Platz für mehr), die Szene hat %3 eingeschaltet: geprüft nur mit den ersten %1</translation>
    </message>
    <message>
        <source>light</source>
        <translation>Lichtquelle</translation>
    </message>
    <message>
        <source>lights</source>
        <translation>Lichtquellen</translation>
    </message>
</context>
<context>
    <name>phonglab::ProgramSynopsis</name>
    <message>
        <source>usage: phonglab [SCENE.json | MESH...]  start the editor on a scene or mesh files
                                        (.obj .ply .off .stl .om; the default scene when none given)
       phonglab SCENE.json --vertex FILE --fragment FILE
                                        the editor on a scene with these shaders (either one alone
                                        keeps the scene&apos;s other stage)
       phonglab &lt;command&gt; [options]     run a command without a window</source>
        <translation>Aufruf: phonglab [SCENE.json | MESH...]  den Editor mit einer Szene oder mit Mesh-Dateien starten
                                         (.obj .ply .off .stl .om; ohne Angabe die Standardszene)
        phonglab SCENE.json --vertex FILE --fragment FILE
                                         den Editor mit einer Szene und diesen Shadern starten (ist nur
                                         einer angegeben, bleibt die andere Stufe der Szene erhalten)
        phonglab &lt;command&gt; [options]     einen Befehl ohne Fenster ausführen</translation>
    </message>
</context>
<context>
    <name>phonglab::ProjectPrograms</name>
    <message>
        <source>%1: not read (a symbolic link, or a path that leaves the project)</source>
        <translation>%1: nicht gelesen (ein symbolischer Link oder ein Pfad, der das Projekt verlässt)</translation>
    </message>
    <message>
        <source>%1: no such file or folder</source>
        <translation>%1: keine solche Datei und kein solcher Ordner</translation>
    </message>
    <message>
        <source>%1 (%2): a %3 shader no program takes</source>
        <translation>%1 (%2): ein %3-Shader, den kein Programm verwendet</translation>
    </message>
    <message>
        <source>vertex</source>
        <translation>Vertex</translation>
    </message>
    <message>
        <source>fragment</source>
        <translation>Fragment</translation>
    </message>
    <message>
        <source>%1: not checked, it lights nothing (no light, material product or shininess in it)</source>
        <translation>%1: nicht beurteilt, es beleuchtet nichts (kein Licht, kein Materialprodukt und keine Glanzzahl darin)</translation>
    </message>
    <message>
        <source>%1: no shader found (no &lt;script&gt; or &lt;textarea&gt; with one, no string in the JavaScript, no .vert/.frag/.glsl file)</source>
        <translation>%1: kein Shader gefunden (kein &lt;script&gt; oder &lt;textarea&gt; mit einem, keine Zeichenkette im JavaScript, keine .vert-/.frag-/.glsl-Datei)</translation>
    </message>
    <message>
        <source>%1: no program named %2 (there are: %3)</source>
        <translation>%1: kein Programm namens %2 (vorhanden: %3)</translation>
    </message>
    <message>
        <source>%1: no program that lights anything (%2)</source>
        <translation>%1: kein Programm, das etwas beleuchtet (%2)</translation>
    </message>
    <message>
        <source>%1: %2 programs light the scene (%3); choose one</source>
        <translation>%1: %2 Programme beleuchten die Szene (%3); eines wählen</translation>
    </message>
</context>
<context>
    <name>phonglab::ProjectSave</name>
    <message>
        <source>the script builds the shader from several strings</source>
        <translation>das Skript setzt den Shader aus mehreren Zeichenketten zusammen</translation>
    </message>
    <message>
        <source>the textarea writes its characters another way than &amp; and &lt; as references</source>
        <translation>das Textfeld schreibt seine Zeichen anders als &amp; und &lt; als Referenzen</translation>
    </message>
    <message>
        <source>the script writes the shader with escapes of its own</source>
        <translation>das Skript schreibt den Shader mit eigenen Escape-Sequenzen</translation>
    </message>
    <message>
        <source>%1: the shader %2 cannot be saved back into the file (%3); use Save As to write it to a file of its own</source>
        <translation>%1: der Shader %2 kann nicht in die Datei zurückgeschrieben werden (%3); mit „Speichern unter“ in eine eigene Datei schreiben</translation>
    </message>
    <message>
        <source>%1 changed on disk; open it again</source>
        <translation>%1 wurde auf dem Datenträger geändert; erneut öffnen</translation>
    </message>
    <message>
        <source>the script element holds &quot;&lt;!--&quot; or &quot;&lt;/script&quot;</source>
        <translation>das script-Element enthält „&lt;!--“ oder „&lt;/script“</translation>
    </message>
    <message>
        <source>%1: the shader %2 holds &quot;&lt;!--&quot; or &quot;&lt;/script&quot;, which would change where its script element ends; use Save As</source>
        <translation>%1: der Shader %2 enthält „&lt;!--“ oder „&lt;/script“, das verschieben würde, wo sein script-Element endet; „Speichern unter“ verwenden</translation>
    </message>
</context>
<context>
    <name>phonglab::ProjectShader</name>
    <message>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <source>%1: no shader named %2 in it</source>
        <translation>%1: kein Shader namens %2 darin</translation>
    </message>
</context>
<context>
    <name>phonglab::RecentFiles</name>
    <message>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
    <message>
        <source>&amp;Clear Recent</source>
        <translation>&amp;Liste leeren</translation>
    </message>
</context>
<context>
    <name>phonglab::RecoveryJournal</name>
    <message>
        <source>%1: cannot create the recovery folder</source>
        <translation>%1: Wiederherstellungsordner kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>%1: cannot lock the recovery journal</source>
        <translation>%1: das Wiederherstellungsjournal kann nicht gesperrt werden</translation>
    </message>
    <message>
        <source>%1: not a complete PhongLab recovery journal</source>
        <translation>%1: kein vollständiges PhongLab-Wiederherstellungsjournal</translation>
    </message>
    <message>
        <source>%1: a shader buffer is missing from the journal</source>
        <translation>%1: im Journal fehlt ein Shader-Puffer</translation>
    </message>
</context>
<context>
    <name>phonglab::ReferenceEdges</name>
    <message>
        <source>The reference is %1x%2 but the edges were cast at another size</source>
        <translation>Die Referenz ist %1x%2 groß, aber die Kanten wurden in einer anderen Größe ermittelt</translation>
    </message>
</context>
<context>
    <name>phonglab::Renderer</name>
    <message>
        <source>cannot build the light-marker program:
</source>
        <translation>das Programm für die Lichtmarkierungen kann nicht gebaut werden:
</translation>
    </message>
    <message>
        <source>cannot upload the light marker: </source>
        <translation>die Lichtmarkierung kann nicht hochgeladen werden: </translation>
    </message>
    <message>
        <source>mesh was not loaded</source>
        <translation>Mesh wurde nicht geladen</translation>
    </message>
    <message>
        <source>%1: not drawn: the shipped %2 shaders did not build</source>
        <translation>%1: nicht gezeichnet: die mitgelieferten Shader für %2 ließen sich nicht bauen</translation>
    </message>
    <message>
        <source>%1: not drawn: %2</source>
        <translation>%1: nicht gezeichnet: %2</translation>
    </message>
</context>
<context>
    <name>phonglab::SceneDock</name>
    <message>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>not loaded</source>
        <translation>nicht geladen</translation>
    </message>
    <message>
        <source>%1 triangles</source>
        <translation>%1 Dreiecke</translation>
    </message>
    <message>
        <source> (detail %1 %)</source>
        <translation> (Detailstufe %1 %)</translation>
    </message>
    <message>
        <source>1 warning</source>
        <translation>1 Warnung</translation>
    </message>
    <message>
        <source>%1 warnings</source>
        <translation>%1 Warnungen</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Vertices</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Dreiecke</translation>
    </message>
    <message>
        <source>Detail</source>
        <translation>Detailstufe</translation>
    </message>
    <message>
        <source>Tessellated coarser (the object&apos;s &quot;detail&quot;)</source>
        <translation>Gröber tesselliert (der Wert &quot;detail&quot; des Objekts)</translation>
    </message>
    <message>
        <source>Decimated from the loaded mesh (the object&apos;s &quot;detail&quot;)</source>
        <translation>Aus dem geladenen Mesh reduziert (der Wert &quot;detail&quot; des Objekts)</translation>
    </message>
    <message>
        <source>Split vertices</source>
        <translation>Aufgeteilte Vertices</translation>
    </message>
    <message>
        <source>Vertices duplicated where a position has several normals</source>
        <translation>Vertices, die verdoppelt werden, wo eine Position mehrere Normalen hat</translation>
    </message>
    <message>
        <source>In the file</source>
        <translation>In der Datei</translation>
    </message>
    <message>
        <source>%1 vertices, %2 faces</source>
        <translation>%1 Vertices, %2 Flächen</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>Normalen</translation>
    </message>
    <message>
        <source>Bounds</source>
        <translation>Ausdehnung</translation>
    </message>
    <message>
        <source>Surface</source>
        <translation>Oberfläche</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Load time</source>
        <translation>Ladezeit</translation>
    </message>
    <message>
        <source>%1 (from the mesh cache)</source>
        <translation>%1 (aus dem Mesh-Cache)</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Warnungen</translation>
    </message>
    <message>
        <source>Select an object to choose how its normals are made</source>
        <translation>Objekt auswählen, um festzulegen, wie seine Normalen erzeugt werden</translation>
    </message>
    <message>
        <source>builtin shapes have exact analytic normals</source>
        <translation>eingebaute Formen haben exakte analytische Normalen</translation>
    </message>
</context>
<context>
    <name>phonglab::SceneDocument</name>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>%1: not a scene file (.json)</source>
        <translation>%1: keine Szenendatei (.json)</translation>
    </message>
    <message>
        <source>%1: no such shader file</source>
        <translation>%1: Shader-Datei existiert nicht</translation>
    </message>
    <message>
        <source>Cannot open the scene&apos;s shaders: %1</source>
        <translation>Die Shader der Szene können nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>Cannot open the scene&apos;s shaders</source>
        <translation>Die Shader der Szene können nicht geöffnet werden</translation>
    </message>
    <message>
        <source>%1

The scene uses its shading method&apos;s shipped shaders instead.</source>
        <translation>%1

Die Szene verwendet stattdessen die mitgelieferten Shader ihres Schattierungsverfahrens.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Cannot render a %1×%2 image</source>
        <translation>Ein %1×%2-Bild kann nicht gerendert werden</translation>
    </message>
    <message>
        <source>Cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>Normals of %1: %2</source>
        <translation>Normalen von %1: %2</translation>
    </message>
    <message>
        <source>Cannot load %1: %2</source>
        <translation>%1 kann nicht geladen werden: %2</translation>
    </message>
    <message>
        <source>Cannot load %1</source>
        <translation>%1 kann nicht geladen werden</translation>
    </message>
    <message>
        <source>Cannot load %1:

%2

The current scene is still shown.</source>
        <translation>%1 kann nicht geladen werden:

%2

Die aktuelle Szene wird weiterhin angezeigt.</translation>
    </message>
    <message>
        <source>Loading %1 cancelled</source>
        <translation>Laden von %1 abgebrochen</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>%1 — PhongLab</source>
        <translation>%1 — PhongLab</translation>
    </message>
</context>
<context>
    <name>phonglab::SceneEditDockSet</name>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>Ctrl+Z</source>
        <translation>Ctrl+Z</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>Ctrl+Shift+Z</source>
        <translation>Ctrl+Shift+Z</translation>
    </message>
</context>
<context>
    <name>phonglab::SceneJson</name>
    <message>
        <source>: unknown key, ignored</source>
        <translation>: unbekannter Schlüssel, ignoriert</translation>
    </message>
    <message>
        <source>expected an object (got %1)</source>
        <translation>Objekt erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>must be a finite number (got %1, out of range)</source>
        <translation>muss eine endliche Zahl sein (erhalten: %1, außerhalb des Bereichs)</translation>
    </message>
    <message>
        <source>expected a number (got %1)</source>
        <translation>Zahl erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>must be a finite number (got %1)</source>
        <translation>muss eine endliche Zahl sein (erhalten: %1)</translation>
    </message>
    <message>
        <source>expected an array of 3 numbers</source>
        <translation>Array aus 3 Zahlen erwartet</translation>
    </message>
    <message>
        <source>must be &gt;= 0 (got %1)</source>
        <translation>muss &gt;= 0 sein (erhalten: %1)</translation>
    </message>
    <message>
        <source>required field missing</source>
        <translation>Pflichtfeld fehlt</translation>
    </message>
    <message>
        <source>expected a string (got %1)</source>
        <translation>Zeichenkette erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>must not be empty (give a file path or &quot;builtin:sphere&quot;)</source>
        <translation>darf nicht leer sein (einen Dateipfad oder &quot;builtin:sphere&quot; angeben)</translation>
    </message>
    <message>
        <source>must not be 0</source>
        <translation>darf nicht 0 sein</translation>
    </message>
    <message>
        <source>must be &gt; 0 (got %1)</source>
        <translation>muss &gt; 0 sein (erhalten: %1)</translation>
    </message>
    <message>
        <source>expected true or false (got %1)</source>
        <translation>true oder false erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>must be in (0, 180) degrees (got %1)</source>
        <translation>muss in (0, 180) Grad liegen (erhalten: %1)</translation>
    </message>
    <message>
        <source>must be greater than near (%1) (got %2)</source>
        <translation>muss größer als near (%1) sein (erhalten: %2)</translation>
    </message>
    <message>
        <source>must differ from eye</source>
        <translation>muss sich von eye unterscheiden</translation>
    </message>
    <message>
        <source>must not be the zero vector</source>
        <translation>darf nicht der Nullvektor sein</translation>
    </message>
    <message>
        <source>must not be parallel to the view direction (target - eye)</source>
        <translation>darf nicht parallel zur Blickrichtung (target - eye) sein</translation>
    </message>
    <message>
        <source>c1 + c2 + c3 must be positive (got %1)</source>
        <translation>c1 + c2 + c3 muss positiv sein (erhalten: %1)</translation>
    </message>
    <message>
        <source>expected an array (got %1)</source>
        <translation>Array erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>at most %1 lights are supported (got %2)</source>
        <translation>höchstens %1 Lichtquellen werden unterstützt (erhalten: %2)</translation>
    </message>
    <message>
        <source>expected a whole number from 1</source>
        <translation>ganze Zahl ab 1 erwartet</translation>
    </message>
    <message>
        <source>: %1 is newer than this PhongLab&apos;s %2; read as %2, fields it does not know are ignored</source>
        <translation>: %1 ist neuer als %2 dieser PhongLab-Version; gelesen als %2, unbekannte Felder werden ignoriert</translation>
    </message>
    <message>
        <source>: &quot;flat&quot; in a scene without &quot;format&quot;: 2 is the per-fragment shader now called &quot;faceted&quot;; loaded as &quot;faceted&quot; (saving writes that; write &quot;format&quot;: 2 for flat shading once per face)</source>
        <translation>: &quot;flat&quot; in einer Szene ohne &quot;format&quot;: 2 ist der Shader pro Fragment, der jetzt &quot;faceted&quot; heißt; als &quot;faceted&quot; geladen (beim Speichern wird das geschrieben; für flache Schattierung, einmal pro Fläche, &quot;format&quot;: 2 schreiben)</translation>
    </message>
    <message>
        <source>unknown shading method &quot;%1&quot; (known: %2)</source>
        <translation>unbekanntes Schattierungsverfahren &quot;%1&quot; (bekannt: %2)</translation>
    </message>
    <message>
        <source>must not be empty (give a shader file path, or leave the key out)</source>
        <translation>darf nicht leer sein (Pfad einer Shader-Datei angeben oder den Schlüssel weglassen)</translation>
    </message>
    <message>
        <source>must list at least one object</source>
        <translation>muss mindestens ein Objekt enthalten</translation>
    </message>
    <message>
        <source>expected a number in (0, 1]</source>
        <translation>Zahl in (0, 1] erwartet</translation>
    </message>
    <message>
        <source>cannot be combined with &quot;mesh&quot; (use one form)</source>
        <translation>kann nicht mit &quot;mesh&quot; kombiniert werden (nur eine Form verwenden)</translation>
    </message>
    <message>
        <source>required field missing (or give &quot;objects&quot;)</source>
        <translation>Pflichtfeld fehlt (oder &quot;objects&quot; angeben)</translation>
    </message>
    <message>
        <source>: ignored with &quot;objects&quot; (give each object its own)</source>
        <translation>: bei &quot;objects&quot; ignoriert (stattdessen bei jedem Objekt einzeln angeben)</translation>
    </message>
    <message>
        <source>top level: expected a JSON object (got array)</source>
        <translation>oberste Ebene: JSON-Objekt erwartet (erhalten: array)</translation>
    </message>
    <message>
        <source>unknown builtin mesh &apos;%1&apos;%2; known: %3</source>
        <translation>unbekanntes eingebautes Mesh &apos;%1&apos;%2; bekannt: %3</translation>
    </message>
    <message>
        <source>cannot read scene file (%1)</source>
        <translation>Szenendatei kann nicht gelesen werden (%1)</translation>
    </message>
    <message>
        <source>a mesh, not a scene: name it in one, {&quot;mesh&quot;: &quot;%1&quot;, &quot;lights&quot;: [{&quot;position&quot;: [3, 4, 5]}]}, saved as a .json file beside it</source>
        <translation>ein Mesh, keine Szene: in einer Szene angeben, {&quot;mesh&quot;: &quot;%1&quot;, &quot;lights&quot;: [{&quot;position&quot;: [3, 4, 5]}]}, als .json-Datei daneben gespeichert</translation>
    </message>
</context>
<context>
    <name>phonglab::SceneJsonText</name>
    <message>
        <source>expected a string (got %1)</source>
        <translation>Zeichenkette erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>unknown normal method &quot;%1&quot; (known: %2)</source>
        <translation>unbekanntes Normalenverfahren &quot;%1&quot; (bekannt: %2)</translation>
    </message>
    <message>
        <source>expected a string or an object (got %1)</source>
        <translation>Zeichenkette oder Objekt erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>unknown key</source>
        <translation>unbekannter Schlüssel</translation>
    </message>
    <message>
        <source>expected a finite number (got %1)</source>
        <translation>endliche Zahl erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>must be in [0, 180] degrees (got %1)</source>
        <translation>muss in [0, 180] Grad liegen (erhalten: %1)</translation>
    </message>
    <message>
        <source>: expected a finite number (got %1)</source>
        <translation>: endliche Zahl erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>: expected an object of name: value (got %1)</source>
        <translation>: Objekt aus Einträgen Name: Wert erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>: a uniform name must not be empty</source>
        <translation>: der Name einer Uniform-Variablen darf nicht leer sein</translation>
    </message>
    <message>
        <source>: expected 1 to 16 numbers (got %1)</source>
        <translation>: 1 bis 16 Zahlen erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>: expected an object of name: meaning (got %1)</source>
        <translation>: Objekt aus Einträgen Name: Bedeutung erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>: a variable name must not be empty</source>
        <translation>: ein Variablenname darf nicht leer sein</translation>
    </message>
    <message>
        <source>: expected a meaning&apos;s name (got %1)</source>
        <translation>: Name einer Bedeutung erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>: unknown meaning &quot;%1&quot; (known: %2, %3)</source>
        <translation>: unbekannte Bedeutung &quot;%1&quot; (bekannt: %2, %3)</translation>
    </message>
    <message>
        <source>: expected an object of NAME: VALUE (got %1)</source>
        <translation>: Objekt aus Einträgen NAME: VALUE erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>: expected the token&apos;s value, a string or a number (got %1)</source>
        <translation>: Wert des Platzhalters erwartet, eine Zeichenkette oder eine Zahl (erhalten: %1)</translation>
    </message>
    <message>
        <source>: expected &quot;highp&quot; or &quot;as-written&quot; (got %1)</source>
        <translation>: &quot;highp&quot; oder &quot;as-written&quot; erwartet (erhalten: %1)</translation>
    </message>
</context>
<context>
    <name>phonglab::SceneJsonWrite</name>
    <message>
        <source>refusing to save an invalid scene: %1</source>
        <translation>ungültige Szene wird nicht gespeichert: %1</translation>
    </message>
    <message>
        <source>%1: cannot write scene file (%2)</source>
        <translation>%1: Szenendatei kann nicht geschrieben werden (%2)</translation>
    </message>
    <message>
        <source>%1: write failed (%2)</source>
        <translation>%1: Schreiben fehlgeschlagen (%2)</translation>
    </message>
</context>
<context>
    <name>phonglab::SceneLoadJob</name>
    <message>
        <source>loading stopped: %1</source>
        <translation>Laden abgebrochen: %1</translation>
    </message>
</context>
<context>
    <name>phonglab::ScenePageJson</name>
    <message>
        <source>: expected an array of strings (got %1)</source>
        <translation>: ein Array von Zeichenketten erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>: expected a string (got %1)</source>
        <translation>: eine Zeichenkette erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>: expected an object (got %1)</source>
        <translation>: ein Objekt erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>: unknown key (known: %1)</source>
        <translation>: unbekannter Schlüssel (bekannt: %1)</translation>
    </message>
    <message>
        <source>: expected a folder&apos;s path (got %1)</source>
        <translation>: der Pfad eines Ordners erwartet (erhalten: %1)</translation>
    </message>
    <message>
        <source>: expected a frame number 1..600 (got %1)</source>
        <translation>: eine Bildnummer 1..600 erwartet (erhalten: %1)</translation>
    </message>
</context>
<context>
    <name>phonglab::ShaderBindings</name>
    <message>
        <source>another type</source>
        <translation>anderer Typ</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: unknown meaning &apos;%2&apos; (known: %3, %4)</source>
        <translation>&apos;%1&apos;: unbekannte Bedeutung &apos;%2&apos; (bekannt: %3, %4)</translation>
    </message>
    <message>
        <source>%1=%2: %1 is a %3%4 %5, which cannot hold %6</source>
        <translation>%1=%2: %1 ist vom Typ %3%4 (%5) und kann %6 nicht aufnehmen</translation>
    </message>
    <message>
        <source>%1=%2: the program has no active uniform or input %1 (not declared, or unused and optimised away)</source>
        <translation>%1=%2: das Programm hat keine aktive Uniform-Variable oder Eingabevariable %1 (nicht deklariert oder unbenutzt und wegoptimiert)</translation>
    </message>
    <message>
        <source> array</source>
        <translation>-Array</translation>
    </message>
    <message>
        <source>input</source>
        <translation>Eingabevariable</translation>
    </message>
    <message>
        <source>uniform</source>
        <translation>Uniform-Variable</translation>
    </message>
    <message>
        <source>the vertex position, object coordinates</source>
        <translation>die Vertex-Position, Objektkoordinaten</translation>
    </message>
    <message>
        <source>the vertex normal, object coordinates</source>
        <translation>die Vertex-Normale, Objektkoordinaten</translation>
    </message>
    <message>
        <source>the model matrix (object to world)</source>
        <translation>die Model-Matrix (Objekt- zu Weltkoordinaten)</translation>
    </message>
    <message>
        <source>the view matrix (world to camera)</source>
        <translation>die View-Matrix (Welt- zu Kamerakoordinaten)</translation>
    </message>
    <message>
        <source>the projection matrix (camera to clip)</source>
        <translation>die Projektionsmatrix (Kamera- zu Clip-Koordinaten)</translation>
    </message>
    <message>
        <source>the model-view matrix (object to camera)</source>
        <translation>die Model-View-Matrix (Objekt- zu Kamerakoordinaten)</translation>
    </message>
    <message>
        <source>the model-view-projection matrix (object to clip)</source>
        <translation>die Model-View-Projection-Matrix (Objekt- zu Clip-Koordinaten)</translation>
    </message>
    <message>
        <source>the view-projection matrix (world to clip)</source>
        <translation>die View-Projection-Matrix (Welt- zu Clip-Koordinaten)</translation>
    </message>
    <message>
        <source>the normal matrix, inverse transpose of the model-view matrix</source>
        <translation>die Normalenmatrix, Inverse der Transponierten der Model-View-Matrix</translation>
    </message>
    <message>
        <source>the inverse transpose of the model matrix</source>
        <translation>die Inverse der Transponierten der Model-Matrix</translation>
    </message>
    <message>
        <source>the camera&apos;s position, world coordinates</source>
        <translation>die Position der Kamera, Weltkoordinaten</translation>
    </message>
    <message>
        <source>the light&apos;s position, world coordinates</source>
        <translation>die Position des Lichts, Weltkoordinaten</translation>
    </message>
    <message>
        <source>the number of lights</source>
        <translation>die Anzahl der Lichter</translation>
    </message>
    <message>
        <source>the light&apos;s diffuse intensity Id</source>
        <translation>die diffuse Intensität Id des Lichts</translation>
    </message>
    <message>
        <source>the light&apos;s specular intensity Is</source>
        <translation>die spekulare Intensität Is des Lichts</translation>
    </message>
    <message>
        <source>the light&apos;s attenuation constants (c1, c2, c3)</source>
        <translation>die Abschwächungskonstanten (c1, c2, c3) des Lichts</translation>
    </message>
    <message>
        <source>the constant attenuation c1</source>
        <translation>die konstante Abschwächung c1</translation>
    </message>
    <message>
        <source>the linear attenuation c2</source>
        <translation>die lineare Abschwächung c2</translation>
    </message>
    <message>
        <source>the quadratic attenuation c3</source>
        <translation>die quadratische Abschwächung c3</translation>
    </message>
    <message>
        <source>the ambient intensity Ia</source>
        <translation>die ambiente Intensität Ia</translation>
    </message>
    <message>
        <source>the ambient reflection ka</source>
        <translation>der ambiente Materialkoeffizient ka</translation>
    </message>
    <message>
        <source>the diffuse reflection kd</source>
        <translation>der diffuse Materialkoeffizient kd</translation>
    </message>
    <message>
        <source>the specular reflection ks</source>
        <translation>der spekulare Materialkoeffizient ks</translation>
    </message>
    <message>
        <source>the shininess n</source>
        <translation>der Glanzexponent n</translation>
    </message>
    <message>
        <source>the ambient product Ia·ka</source>
        <translation>das ambiente Produkt Ia·ka</translation>
    </message>
    <message>
        <source>the light&apos;s diffuse product Id·kd</source>
        <translation>das diffuse Produkt Id·kd des Lichts</translation>
    </message>
    <message>
        <source>the light&apos;s specular product Is·ks</source>
        <translation>das spekulare Produkt Is·ks des Lichts</translation>
    </message>
    <message>
        <source>the light&apos;s colour, both Id and Is</source>
        <translation>die Farbe des Lichts, Id und Is zugleich</translation>
    </message>
    <message>
        <source>the material&apos;s colour, both ka and kd</source>
        <translation>die Farbe des Materials, ka und kd zugleich</translation>
    </message>
    <message>
        <source>the light&apos;s position, camera coordinates</source>
        <translation>die Position des Lichts, Kamerakoordinaten</translation>
    </message>
    <message>
        <source>a gain whose term&apos;s other factors hold its whole value: 1</source>
        <translation>ein Faktor, dessen Term seinen ganzen Wert schon in den anderen Faktoren hat: 1</translation>
    </message>
    <message>
        <source>Ia, Id and Is of light 0, as a mat3&apos;s columns or a vec3[3]</source>
        <translation>Ia, Id und Is von Licht 0, als Spalten einer mat3 oder als vec3[3]</translation>
    </message>
    <message>
        <source>ka, kd and ks, as a mat3&apos;s columns or a vec3[3]</source>
        <translation>ka, kd und ks, als Spalten einer mat3 oder als vec3[3]</translation>
    </message>
</context>
<context>
    <name>phonglab::ShaderCheck</name>
    <message>
        <source>PSNR %1 dB</source>
        <translation>PSNR %1 dB</translation>
    </message>
    <message>
        <source> (or %1)</source>
        <translation> (oder %1)</translation>
    </message>
    <message>
        <source>✓ matches the exact image (%1, max %2/255)</source>
        <translation>✓ stimmt mit dem exakten Bild überein (%1, max. %2/255)</translation>
    </message>
    <message>
        <source>✗ %1, max %2/255, %3 % of pixels off</source>
        <translation>✗ %1, max. %2/255, %3 % der Pixel weichen ab</translation>
    </message>
    <message>
        <source> — unknown: no classic mistake explains it; see the heatmap</source>
        <translation> — unknown: kein typischer Fehler erklärt das; siehe Heatmap</translation>
    </message>
    <message>
        <source> — %1 (%2 %, %3): %4</source>
        <translation> — %1 (%2 %, %3): %4</translation>
    </message>
    <message>
        <source> or </source>
        <translation> oder </translation>
    </message>
    <message>
        <source> — %1 mistakes together (%2 %): %3</source>
        <translation> — %1 Fehler zusammen (%2 %): %3</translation>
    </message>
    <message>
        <source>✓ %1 — the slide&apos;s equation</source>
        <translation>✓ %1 — die Gleichung der Folie</translation>
    </message>
    <message>
        <source> — not checked here: %1</source>
        <translation> — hier nicht geprüft: %1</translation>
    </message>
    <message>
        <source>✗ %1 — %2</source>
        <translation>✗ %1 — %2</translation>
    </message>
    <message>
        <source>✗ %1 — no classic mistake explains it</source>
        <translation>✗ %1 — kein klassischer Fehler erklärt es</translation>
    </message>
</context>
<context>
    <name>phonglab::ShaderDock</name>
    <message>
        <source>Shaders</source>
        <translation>Shader</translation>
    </message>
    <message>
        <source>Apply anyway</source>
        <translation>Trotzdem anwenden</translation>
    </message>
    <message>
        <source>Draw with this program although its frames are slow; the view then draws only when you ask it to</source>
        <translation>Mit diesem Programm zeichnen, obwohl seine Frames langsam sind; die Ansicht zeichnet dann nur noch auf Anforderung</translation>
    </message>
    <message>
        <source>Load a shading method&apos;s shaders</source>
        <translation>Shader eines Schattierungsverfahrens laden</translation>
    </message>
    <message>
        <source>Compile</source>
        <translation>Kompilieren</translation>
    </message>
    <message>
        <source>Compile and link both stages (F5)</source>
        <translation>Beide Stufen kompilieren und linken (F5)</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Öffnen…</translation>
    </message>
    <message>
        <source>Open a shader, or a .vert/.frag pair</source>
        <translation>Einen Shader oder ein .vert/.frag-Paar öffnen</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Save the current tab (shipped shaders are saved as a user copy)</source>
        <translation>Aktuellen Tab speichern (mitgelieferte Shader werden als Benutzerkopie gespeichert)</translation>
    </message>
    <message>
        <source>Save As…</source>
        <translation>Speichern unter…</translation>
    </message>
    <message>
        <source>Save the current tab under another name</source>
        <translation>Aktuellen Tab unter einem anderen Namen speichern</translation>
    </message>
    <message>
        <source>Open one shader, or a vertex and a fragment shader.</source>
        <translation>Bitte einen Shader oder einen Vertex- und einen Fragment-Shader öffnen.</translation>
    </message>
    <message>
        <source>%1: cannot tell which stage it is (use .vert or .frag)</source>
        <translation>%1: Stufe nicht erkennbar (.vert oder .frag verwenden)</translation>
    </message>
    <message>
        <source>Both files are %1 shaders.</source>
        <translation>Beide Dateien sind %1-Shader.</translation>
    </message>
    <message>
        <source>%1 shader</source>
        <translation>%1-Shader</translation>
    </message>
    <message>
        <source>
Shipped with PhongLab: edits go to a user copy.</source>
        <translation>
Mit PhongLab mitgeliefert: Änderungen werden in einer Benutzerkopie gespeichert.</translation>
    </message>
    <message>
        <source>%1 (your shader)</source>
        <translation>%1 (eigener Shader)</translation>
    </message>
</context>
<context>
    <name>phonglab::ShaderEditor</name>
    <message>
        <source>Error annotation</source>
        <translation>Fehleranmerkung</translation>
    </message>
    <message>
        <source>Warning annotation</source>
        <translation>Warnungsanmerkung</translation>
    </message>
    <message>
        <source>Ctrl+Space</source>
        <translation>Ctrl+Space</translation>
    </message>
    <message>
        <source>Ctrl+Shift+Space</source>
        <translation>Ctrl+Shift+Space</translation>
    </message>
    <message>
        <source>Check annotation</source>
        <translation>Prüfungshinweis</translation>
    </message>
</context>
<context>
    <name>phonglab::ShaderFileDialogs</name>
    <message>
        <source>Shaders</source>
        <translation>Shader</translation>
    </message>
    <message>
        <source>Save As…</source>
        <translation>Speichern unter…</translation>
    </message>
    <message>
        <source>Save Shader As</source>
        <translation>Shader speichern unter</translation>
    </message>
</context>
<context>
    <name>phonglab::ShaderFileSet</name>
    <message>
        <source>%1: cannot create the folder for user shaders</source>
        <translation>%1: Der Ordner für eigene Shader kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>%1 is a shader shipped with PhongLab and is never overwritten; save under another name or folder.</source>
        <translation>%1 ist ein mit PhongLab mitgelieferter Shader und wird nie überschrieben; bitte unter einem anderen Namen oder in einem anderen Ordner speichern.</translation>
    </message>
    <message>
        <source>Shader changed on disk</source>
        <translation>Shader auf dem Datenträger geändert</translation>
    </message>
    <message>
        <source>%1 was changed by another program, and the editor has unsaved changes to it.</source>
        <translation>%1 wurde von einem anderen Programm geändert, und der Editor enthält ungespeicherte Änderungen daran.</translation>
    </message>
    <message>
        <source>Reload it and lose your changes, or keep your version?</source>
        <translation>Neu laden und die Änderungen verwerfen oder die eigene Version behalten?</translation>
    </message>
    <message>
        <source>Reload</source>
        <translation>Neu laden</translation>
    </message>
    <message>
        <source>Keep mine</source>
        <translation>Eigene behalten</translation>
    </message>
    <message>
        <source>GLSL shaders (%1);;All files (*)</source>
        <translation>GLSL-Shader (%1);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>phonglab::ShaderLint</name>
    <message>
        <source>the output &apos;%1&apos; is read before it is written: its value is undefined in GLSL; a browser&apos;s WebGL starts it at 0 and PhongLab checks it so, but a GPU elsewhere may keep what was there</source>
        <translation>die Ausgabe &apos;%1&apos; wird gelesen, bevor sie geschrieben wird: ihr Wert ist in GLSL undefiniert; das WebGL eines Browsers setzt sie auf 0 und PhongLab prüft sie so, aber eine andere GPU kann behalten, was dort stand</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is read before it is set: its value is undefined in GLSL; a browser&apos;s WebGL starts it at 0 and PhongLab checks it so, but a GPU elsewhere may keep what was there</source>
        <translation>&apos;%1&apos; wird gelesen, bevor es gesetzt wird: sein Wert ist in GLSL undefiniert; das WebGL eines Browsers setzt ihn auf 0 und PhongLab prüft ihn so, aber eine andere GPU kann behalten, was dort stand</translation>
    </message>
</context>
<context>
    <name>phonglab::ShaderMistake</name>
    <message>
        <source>the normal N: it must be transformed by the inverse transpose of the model-view matrix, not by the model-view or model matrix, nor by a transpose without the inverse (which bends it under non-uniform scale)</source>
        <translation>die Normale N: Bei der Normalentransformation muss sie mit der Inversen der Transponierten der Model-View-Matrix transformiert werden, nicht mit der Model-View- oder der Model-Matrix und auch nicht mit der Transponierten ohne Inverse (die sie bei nicht gleichmäßiger Skalierung verbiegt)</translation>
    </message>
    <message>
        <source>the normal N: it must be normalised in the fragment shader, after interpolation has shortened it (and L and V must be unit length too)</source>
        <translation>die Normale N: Sie muss im Fragment-Shader normalisiert werden, nachdem die Interpolation sie verkürzt hat (auch L und V müssen die Länge 1 haben)</translation>
    </message>
    <message>
        <source>the light vector L: the light is placed in world coordinates and must be moved into camera coordinates by the view matrix (not left as it is, nor moved by the model-view matrix) before L = light - P</source>
        <translation>der Lichtvektor L: Die Lichtquelle ist in Weltkoordinaten gegeben und muss mit der View-Matrix in Kamerakoordinaten überführt werden (weder unverändert bleiben noch mit der Model-View-Matrix transformiert werden), bevor L = light - P berechnet wird</translation>
    </message>
    <message>
        <source>points and directions: a point (the position P, the light&apos;s position) is transformed with w = 1, a direction (the normal) with w = 0; a point with w = 0 loses the translation, a direction with w = 1 gains it</source>
        <translation>Punkte und Richtungsvektoren: Ein Punkt (die Position P, die Position der Lichtquelle) wird mit w = 1 transformiert, ein Richtungsvektor (die Normale) mit w = 0; ein Punkt mit w = 0 verliert die Translation, ein Richtungsvektor mit w = 1 erhält sie fälschlich</translation>
    </message>
    <message>
        <source>the specular term: R must be reflect(-L, N); reflect() takes the incident vector, which points from the light to the surface</source>
        <translation>der spekulare Anteil: R muss reflect(-L, N) sein; reflect() erwartet den Einfallsvektor, der von der Lichtquelle zur Oberfläche zeigt</translation>
    </message>
    <message>
        <source>the specular term: V must point from the surface to the eye, V = normalize(-P) in camera coordinates</source>
        <translation>der spekulare Anteil: V muss von der Oberfläche zum Auge zeigen, V = normalize(-P) in Kamerakoordinaten</translation>
    </message>
    <message>
        <source>the attenuation f_att = min(1 / (c1 + c2·d + c3·d²), 1) must scale each light&apos;s diffuse and specular parts, with d the distance from the surface to the light, and never exceed 1</source>
        <translation>der Abschwächungsfaktor f_att = min(1 / (c1 + c2·d + c3·d²), 1) muss den diffusen und den spekularen Anteil jeder Lichtquelle skalieren, mit d als Abstand von der Oberfläche zur Lichtquelle, und darf nie größer als 1 sein</translation>
    </message>
    <message>
        <source>the diffuse term: N·L must be clamped with max(0, N·L); a light behind the surface adds nothing, it does not darken</source>
        <translation>der diffuse Anteil: N·L muss mit max(0, N·L) begrenzt werden; eine Lichtquelle hinter der Oberfläche trägt nichts bei, sie verdunkelt nicht</translation>
    </message>
    <message>
        <source>the specular term: where N·L &lt;= 0 the light is behind the surface and there is no highlight either</source>
        <translation>der spekulare Anteil: Wo N·L &lt;= 0 ist, liegt die Lichtquelle hinter der Oberfläche, und es gibt auch kein Glanzlicht</translation>
    </message>
    <message>
        <source>the ambient term Ia·ka must be added once, outside the sum over the lights</source>
        <translation>der ambiente Anteil Ia·ka muss einmal addiert werden, außerhalb der Summe über die Lichtquellen</translation>
    </message>
    <message>
        <source>where the equation is evaluated: per fragment, with the interpolated normal; evaluated per vertex and interpolated, highlights smear and vanish between vertices</source>
        <translation>wo die Beleuchtungsgleichung ausgewertet wird: pro Fragment, mit der interpolierten Normale; wird sie pro Vertex ausgewertet und interpoliert, verschmieren die Glanzlichter und verschwinden zwischen den Vertices</translation>
    </message>
    <message>
        <source>N moved by the model-view matrix, not its inverse transpose</source>
        <translation>N mit der Model-View-Matrix transformiert statt mit der Inversen ihrer Transponierten</translation>
    </message>
    <message>
        <source>N not normalised after interpolation</source>
        <translation>N nach der Interpolation nicht normalisiert</translation>
    </message>
    <message>
        <source>the light&apos;s world position used as a camera-space one</source>
        <translation>die Lichtposition in Weltkoordinaten als Position in Kamerakoordinaten verwendet</translation>
    </message>
    <message>
        <source>the position moved with w = 0</source>
        <translation>die Position mit w = 0 transformiert</translation>
    </message>
    <message>
        <source>reflect(L, N) instead of reflect(-L, N)</source>
        <translation>reflect(L, N) statt reflect(-L, N)</translation>
    </message>
    <message>
        <source>V points away from the eye</source>
        <translation>V zeigt vom Auge weg</translation>
    </message>
    <message>
        <source>f_att missing or wrong</source>
        <translation>f_att fehlt oder ist falsch</translation>
    </message>
    <message>
        <source>N·L not clamped with max(0, ·)</source>
        <translation>N·L nicht mit max(0, ·) begrenzt</translation>
    </message>
    <message>
        <source>a highlight where N·L &lt;= 0</source>
        <translation>ein Glanzlicht, wo N·L &lt;= 0 ist</translation>
    </message>
    <message>
        <source>Ia·ka missing or wrong</source>
        <translation>Ia·ka fehlt oder ist falsch</translation>
    </message>
    <message>
        <source>lit per vertex, not per fragment</source>
        <translation>pro Vertex beleuchtet statt pro Fragment</translation>
    </message>
    <message>
        <source>N moved by the model matrix alone</source>
        <translation>N nur mit der Model-Matrix transformiert</translation>
    </message>
    <message>
        <source>N moved by the transpose of the model-view matrix, without the inverse</source>
        <translation>N mit der Transponierten der Model-View-Matrix transformiert, ohne Inverse</translation>
    </message>
    <message>
        <source>L not normalised</source>
        <translation>L nicht normalisiert</translation>
    </message>
    <message>
        <source>the light moved by the model-view matrix, not the view matrix</source>
        <translation>die Lichtquelle mit der Model-View-Matrix statt mit der View-Matrix transformiert</translation>
    </message>
    <message>
        <source>the light&apos;s position moved with w = 0</source>
        <translation>die Lichtposition mit w = 0 transformiert</translation>
    </message>
    <message>
        <source>the normal, a direction, moved with w = 1</source>
        <translation>die Normale, ein Richtungsvektor, mit w = 1 transformiert</translation>
    </message>
    <message>
        <source>f_att not clamped with min(..., 1)</source>
        <translation>f_att nicht mit min(..., 1) begrenzt</translation>
    </message>
    <message>
        <source>Ia·ka added once per light</source>
        <translation>Ia·ka einmal pro Lichtquelle addiert</translation>
    </message>
    <message>
        <source>which normal: the one interpolated across the face from the vertices&apos; normals; with each face&apos;s own normal the surface shows its facets</source>
        <translation>welche Normale: die aus den Normalen der Vertices über die Fläche interpolierte; mit der eigenen Normale jeder Fläche zeigt die Oberfläche ihre Facetten</translation>
    </message>
    <message>
        <source>lit once per face with its normal (flat shading)</source>
        <translation>einmal pro Fläche mit ihrer Normale beleuchtet (flache Schattierung)</translation>
    </message>
    <message>
        <source>lit per fragment with the face&apos;s normal (faceted shading)</source>
        <translation>pro Fragment mit der Normale der Fläche beleuchtet (facettierte Schattierung)</translation>
    </message>
    <message>
        <source>the specular term: Phong&apos;s is max(0, R·V)^n with R = reflect(-L, N); Blinn&apos;s N·H with the halfway vector H = normalize(L + V) gives a wider highlight</source>
        <translation>der spekulare Anteil: bei Phong max(0, R·V)^n mit R = reflect(-L, N); Blinns N·H mit dem Halbvektor H = normalize(L + V) ergibt ein breiteres Glanzlicht</translation>
    </message>
    <message>
        <source>N·H with the halfway vector in place of R·V</source>
        <translation>N·H mit dem Halbvektor statt R·V</translation>
    </message>
    <message>
        <source>f_att hard-coded as 1 / d², not the light&apos;s c1, c2, c3</source>
        <translation>f_att fest als 1 / d² geschrieben statt mit c1, c2, c3 der Lichtquelle</translation>
    </message>
    <message>
        <source>f_att hard-coded as 1 / (1 + 0.09·d + 0.032·d²), not the light&apos;s c1, c2, c3</source>
        <translation>f_att fest als 1 / (1 + 0,09·d + 0,032·d²) geschrieben statt mit c1, c2, c3 der Lichtquelle</translation>
    </message>
    <message>
        <source>Ia·ka added inside the light loop, scaled by f_att</source>
        <translation>Ia·ka in der Schleife über die Lichtquellen addiert, mit f_att abgeschwächt</translation>
    </message>
    <message>
        <source>N·H with the halfway vector and the exponent 4n in place of R·V</source>
        <translation>N·H mit dem Halbvektor und dem Exponenten 4n statt R·V</translation>
    </message>
</context>
<context>
    <name>phonglab::ShaderRecovery</name>
    <message>
        <source>Discarded the shader edits recovered from %1</source>
        <translation>Die geretteten Shader-Änderungen vom %1 wurden verworfen</translation>
    </message>
    <message>
        <source>Restored the shader edits recovered from %1</source>
        <translation>Die geretteten Shader-Änderungen vom %1 wurden wiederhergestellt</translation>
    </message>
    <message>
        <source>Restored shaders were running when PhongLab stopped unexpectedly, so they were not compiled; the shipped program is shown. Press F5 to compile them.</source>
        <translation>Die wiederhergestellten Shader liefen, als PhongLab unerwartet beendet wurde, und wurden deshalb nicht kompiliert; angezeigt wird das mitgelieferte Programm. Zum Kompilieren F5 drücken.</translation>
    </message>
    <message>
        <source>PhongLab stopped unexpectedly while trying a new shader; the restored shaders were not compiled and the shipped program is shown. Press F5 to compile them.</source>
        <translation>PhongLab wurde beim Ausprobieren eines neuen Shaders unerwartet beendet; die wiederhergestellten Shader wurden nicht kompiliert, angezeigt wird das mitgelieferte Programm. Zum Kompilieren F5 drücken.</translation>
    </message>
    <message>
        <source>Recover shader edits</source>
        <translation>Shader-Änderungen wiederherstellen</translation>
    </message>
    <message>
        <source>PhongLab did not shut down cleanly. Shader edits from %1 were recovered.

Restore them into the editor?</source>
        <translation>PhongLab wurde nicht ordnungsgemäß beendet. Shader-Änderungen vom %1 wurden gerettet.

Sollen sie im Editor wiederhergestellt werden?</translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Wiederherstellen</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>A new shader was running when it stopped; it will not be compiled until you press F5.</source>
        <translation>Als PhongLab beendet wurde, lief ein neuer Shader; er wird erst kompiliert, wenn F5 gedrückt wird.</translation>
    </message>
    <message>
        <source>Unsaved shader changes</source>
        <translation>Ungespeicherte Shader-Änderungen</translation>
    </message>
    <message>
        <source>The shaders have unsaved changes. Save them before quitting?</source>
        <translation>Die Shader haben ungespeicherte Änderungen. Vor dem Beenden speichern?</translation>
    </message>
    <message>
        <source>Cannot save shader</source>
        <translation>Shader kann nicht gespeichert werden</translation>
    </message>
</context>
<context>
    <name>phonglab::ShaderSource</name>
    <message>
        <source>%1: cannot read shader: %2</source>
        <translation>%1: Shader kann nicht gelesen werden: %2</translation>
    </message>
</context>
<context>
    <name>phonglab::ShortcutsDialog</name>
    <message>
        <source>3D view</source>
        <translation>3D-Ansicht</translation>
    </message>
    <message>
        <source>%1 dock</source>
        <translation>Dock „%1“</translation>
    </message>
    <message>
        <source>window</source>
        <translation>Fenster</translation>
    </message>
    <message>
        <source>anywhere in PhongLab</source>
        <translation>überall in PhongLab</translation>
    </message>
    <message>
        <source>anywhere in the window</source>
        <translation>überall im Fenster</translation>
    </message>
    <message>
        <source>toolbar</source>
        <translation>Werkzeugleiste</translation>
    </message>
    <message>
        <source>while the %1 has the focus</source>
        <translation>bei Fokus auf %1</translation>
    </message>
    <message>
        <source> or the </source>
        <translation> oder </translation>
    </message>
    <message>
        <source>%1 toolbar</source>
        <translation>Werkzeugleiste „%1“</translation>
    </message>
    <message>
        <source>Window</source>
        <translation>Fenster</translation>
    </message>
    <message>
        <source>Keyboard Shortcuts — PhongLab</source>
        <translation>Tastenkürzel — PhongLab</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>Befehl</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <source>Works</source>
        <translation>Gilt</translation>
    </message>
</context>
<context>
    <name>phonglab::SilentTerms</name>
    <message>
        <source>Ia = 0</source>
        <translation>Ia = 0</translation>
    </message>
    <message>
        <source>ka = 0 on every object</source>
        <translation>ka = 0 bei jedem Objekt</translation>
    </message>
    <message>
        <source>no light is on</source>
        <translation>keine Lichtquelle ist eingeschaltet</translation>
    </message>
    <message>
        <source>Id = 0 for every light</source>
        <translation>Id = 0 bei jeder Lichtquelle</translation>
    </message>
    <message>
        <source>Is = 0 for every light</source>
        <translation>Is = 0 bei jeder Lichtquelle</translation>
    </message>
    <message>
        <source>kd = 0 on every object</source>
        <translation>kd = 0 bei jedem Objekt</translation>
    </message>
    <message>
        <source>ks = 0 on every object</source>
        <translation>ks = 0 bei jedem Objekt</translation>
    </message>
    <message>
        <source>ambient</source>
        <translation>ambient</translation>
    </message>
    <message>
        <source>diffuse</source>
        <translation>diffus</translation>
    </message>
    <message>
        <source>specular</source>
        <translation>spekular</translation>
    </message>
    <message>
        <source>the %1 term (%2)</source>
        <translation>der Anteil %1 (%2)</translation>
    </message>
</context>
<context>
    <name>phonglab::SpeedAccuracyChart</name>
    <message>
        <source>frame time (ms, median)</source>
        <translation>Framezeit (ms, Median)</translation>
    </message>
    <message>
        <source>8-bit steps</source>
        <translation>8-Bit-Stufen</translation>
    </message>
    <message>
        <source>no normal-study rows to chart</source>
        <translation>keine Zeilen der Normalenstudie für ein Diagramm</translation>
    </message>
    <message>
        <source>Normal methods: time against angular error</source>
        <translation>Normalenverfahren: Zeit gegenüber Winkelfehler</translation>
    </message>
    <message>
        <source>time (ms)</source>
        <translation>Zeit (ms)</translation>
    </message>
    <message>
        <source>mean angular error (degrees)</source>
        <translation>mittlerer Winkelfehler (Grad)</translation>
    </message>
    <message>
        <source>panel size %1×%2 is empty</source>
        <translation>Diagrammfläche %1×%2 ist leer</translation>
    </message>
    <message>
        <source>no benchmark rows to chart</source>
        <translation>keine Benchmark-Zeilen für ein Diagramm</translation>
    </message>
    <message>
        <source>PhongLab: frame time against error</source>
        <translation>PhongLab: Framezeit gegenüber Fehler</translation>
    </message>
    <message>
        <source>error: RMSE</source>
        <translation>Fehler: RMSE</translation>
    </message>
</context>
<context>
    <name>phonglab::UniformFloatRow</name>
    <message>
        <source>Refused: %1</source>
        <translation>Abgelehnt: %1</translation>
    </message>
</context>
<context>
    <name>phonglab::UniformNumberField</name>
    <message>
        <source>“%1” is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
    <message>
        <source>not a number (NaN)</source>
        <translation>keine Zahl (NaN)</translation>
    </message>
    <message>
        <source>not a finite number</source>
        <translation>keine endliche Zahl</translation>
    </message>
    <message>
        <source>%1 is outside the range %2 … %3</source>
        <translation>%1 liegt außerhalb des Bereichs %2 … %3</translation>
    </message>
    <message>
        <source>Refused: %1. The value stays %2.</source>
        <translation>Abgelehnt: %1. Der Wert bleibt %2.</translation>
    </message>
</context>
<context>
    <name>phonglab::UniformVectorRow</name>
    <message>
        <source>Refused: %1</source>
        <translation>Abgelehnt: %1</translation>
    </message>
    <message>
        <source>Choose a colour</source>
        <translation>Farbe auswählen</translation>
    </message>
</context>
<context>
    <name>phonglab::UniformsDock</name>
    <message>
        <source>Uniforms</source>
        <translation>Uniform-Variablen</translation>
    </message>
    <message>
        <source>declared but optimised away: not used by the program</source>
        <translation>deklariert, aber wegoptimiert: vom Programm nicht verwendet</translation>
    </message>
    <message>
        <source>The compiler removed %1 %2 because nothing the output depends on reads it.</source>
        <translation>Der Compiler hat %1 %2 entfernt, weil nichts, wovon die Ausgabe abhängt, diese Variable liest.</translation>
    </message>
    <message>
        <source>by its use: %1 (%2 shader, line %3)</source>
        <translation>nach Verwendung: %1 (%2-Shader, Zeile %3)</translation>
    </message>
    <message>
        <source>bound to nothing: choose what it is</source>
        <translation>nichts zugeordnet: auswählen, was sie ist</translation>
    </message>
</context>
<context>
    <name>phonglab::Vec3Field</name>
    <message>
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <source>Pick as a colour</source>
        <translation>Als Farbe wählen</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation>%1: &quot;%2&quot; ist keine Zahl</translation>
    </message>
    <message>
        <source>%1: NaN is not allowed</source>
        <translation>%1: NaN ist nicht erlaubt</translation>
    </message>
    <message>
        <source>%1: must be finite</source>
        <translation>%1: muss endlich sein</translation>
    </message>
    <message>
        <source>%1: must be in [%2, %3] (got %4)</source>
        <translation>%1: muss in [%2, %3] liegen (erhalten: %4)</translation>
    </message>
</context>
<context>
    <name>phonglab::VerdictDock</name>
    <message>
        <source>Check</source>
        <translation>Prüfung</translation>
    </message>
    <message>
        <source>The check&apos;s verdict appears here once the first frame is checked.</source>
        <translation>Das Prüfungsergebnis erscheint hier, sobald das erste Bild geprüft ist.</translation>
    </message>
    <message>
        <source>The code in the editor does not compile: this is the verdict of the last program that did, which is still drawn.</source>
        <translation>Der Code im Editor lässt sich nicht kompilieren: Dies ist das Urteil über das letzte Programm, das sich kompilieren ließ und weiterhin gezeichnet wird.</translation>
    </message>
</context>
<context>
    <name>phonglab::ViewMenu</name>
    <message>
        <source>&amp;Reset Camera</source>
        <translation>&amp;Kamera zurücksetzen</translation>
    </message>
    <message>
        <source>Reset &amp;Layout</source>
        <translation>&amp;Layout zurücksetzen</translation>
    </message>
    <message>
        <source>Put every dock back where a new window has it</source>
        <translation>Jedes Dock dorthin zurücksetzen, wo es in einem neuen Fenster liegt</translation>
    </message>
    <message>
        <source>Show &amp;Light Markers</source>
        <translation>Licht&amp;markierungen anzeigen</translation>
    </message>
    <message>
        <source>&amp;Scene Dock</source>
        <translation>&amp;Szenen-Dock</translation>
    </message>
    <message>
        <source>S&amp;haders Dock</source>
        <translation>S&amp;hader-Dock</translation>
    </message>
    <message>
        <source>&amp;Uniforms Dock</source>
        <translation>&amp;Uniform-Variablen-Dock</translation>
    </message>
    <message>
        <source>&amp;Performance Dock</source>
        <translation>&amp;Leistungs-Dock</translation>
    </message>
    <message>
        <source>L&amp;anguage</source>
        <translation>Sp&amp;rache</translation>
    </message>
</context>
<context>
    <name>phonglab::Viewport</name>
    <message>
        <source>Cannot render with %1: %2</source>
        <translation>Rendern mit %1 nicht möglich: %2</translation>
    </message>
</context>
<context>
    <name>phonglab::ViewportSurface</name>
    <message>
        <source>Cannot create an OpenGL context for the viewport</source>
        <translation>Für die Ansicht kann kein OpenGL-Kontext erstellt werden</translation>
    </message>
</context>
<context>
    <name>phonglab::WarmUpDraw</name>
    <message>
        <source>cannot create the %1-sample framebuffer for warming programs</source>
        <translation>der Framebuffer mit %1 Samples zum Aufwärmen der Programme kann nicht erstellt werden</translation>
    </message>
</context>
<context>
    <name>phonglab::WebGl1Limits</name>
    <message>
        <source>WebGL 1 has no %1 loops (GLSL ES 1.00, appendix A): the browser refuses this shader (&quot;This type of loop is not allowed&quot;); write a for loop with a constant bound</source>
        <translation>WebGL 1 kennt keine %1-Schleifen (GLSL ES 1.00, Anhang A): der Browser lehnt diesen Shader ab (&quot;This type of loop is not allowed&quot;); eine for-Schleife mit konstanter Grenze schreiben</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is no constant: WebGL 1 starts a loop&apos;s index at a constant, and the browser refuses this shader (&quot;Loop index cannot be initialized with non-constant expression&quot;)</source>
        <translation>&apos;%1&apos; ist keine Konstante: WebGL 1 beginnt den Index einer Schleife bei einer Konstanten, und der Browser lehnt diesen Shader ab (&quot;Loop index cannot be initialized with non-constant expression&quot;)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is no constant: WebGL 1 compares a loop&apos;s index with a constant, and the browser refuses this shader (&quot;Loop index cannot be compared with non-constant expression&quot;); bound the loop by a constant and break at the count</source>
        <translation>&apos;%1&apos; ist keine Konstante: WebGL 1 vergleicht den Index einer Schleife mit einer Konstanten, und der Browser lehnt diesen Shader ab (&quot;Loop index cannot be compared with non-constant expression&quot;); die Schleife durch eine Konstante begrenzen und bei der Anzahl mit break abbrechen</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::BenchArgs</name>
    <message>
        <source>usage: phonglab bench [--scene FILE ...] [--quick] [--out DIR] [--budget SPEC] [--size WxH]
                      [--frames N] [--lights LIST] [--methods LIST] [--details LIST] [--images] [--normals]
       phonglab bench --from results.csv [--out DIR] [--budget SPEC]
       phonglab bench --path orbit|dolly|FILE.json [--path-frames N] [--scene FILE ...] [--out DIR]
                      [--budget SPEC] [--size WxH] [--frames N] [--images]</source>
        <translation>Aufruf: phonglab bench [--scene FILE ...] [--quick] [--out DIR] [--budget SPEC] [--size WxH]
                       [--frames N] [--lights LIST] [--methods LIST] [--details LIST] [--images] [--normals]
        phonglab bench --from results.csv [--out DIR] [--budget SPEC]
        phonglab bench --path orbit|dolly|FILE.json [--path-frames N] [--scene FILE ...] [--out DIR]
                       [--budget SPEC] [--size WxH] [--frames N] [--images]</translation>
    </message>
    <message>
        <source>Show help.</source>
        <translation>Hilfe anzeigen.</translation>
    </message>
    <message>
        <source>Scene file.</source>
        <translation>Szenendatei.</translation>
    </message>
    <message>
        <source>Short run.</source>
        <translation>Kurzer Lauf.</translation>
    </message>
    <message>
        <source>Output folder.</source>
        <translation>Ausgabeordner.</translation>
    </message>
    <message>
        <source>Error budget.</source>
        <translation>Fehlerbudget.</translation>
    </message>
    <message>
        <source>Frame size.</source>
        <translation>Bildgröße.</translation>
    </message>
    <message>
        <source>Timed frames.</source>
        <translation>Gemessene Frames.</translation>
    </message>
    <message>
        <source>Light counts.</source>
        <translation>Anzahl der Lichtquellen.</translation>
    </message>
    <message>
        <source>Detail fractions.</source>
        <translation>Anteile der Detailstufen.</translation>
    </message>
    <message>
        <source>Write pictures.</source>
        <translation>Bilder schreiben.</translation>
    </message>
    <message>
        <source>Normal-method study.</source>
        <translation>Studie der Normalenverfahren.</translation>
    </message>
    <message>
        <source>Earlier results.</source>
        <translation>Frühere Ergebnisse.</translation>
    </message>
    <message>
        <source>Camera path.</source>
        <translation>Kamerapfad.</translation>
    </message>
    <message>
        <source>Path frames.</source>
        <translation>Frames des Pfads.</translation>
    </message>
    <message>
        <source>unexpected argument &apos;%1&apos; (scenes go after --scene)</source>
        <translation>unerwartetes Argument &apos;%1&apos; (Szenen gehören hinter --scene)</translation>
    </message>
    <message>
        <source>--from measures nothing: --%1 does not go with it</source>
        <translation>--from misst nichts: --%1 passt nicht dazu</translation>
    </message>
    <message>
        <source>--from: empty file name</source>
        <translation>--from: leerer Dateiname</translation>
    </message>
    <message>
        <source>--path measures a camera path: --%1 does not go with it</source>
        <translation>--path misst einen Kamerapfad: --%1 passt nicht dazu</translation>
    </message>
    <message>
        <source>--path: expected orbit, dolly or a keyframe file</source>
        <translation>--path: orbit, dolly oder eine Keyframe-Datei erwartet</translation>
    </message>
    <message>
        <source>--path-frames goes with --path orbit or --path dolly</source>
        <translation>--path-frames gehört zu --path orbit oder --path dolly</translation>
    </message>
    <message>
        <source>--path-frames: expected a whole number from 2 to 10000, got &apos;%1&apos;</source>
        <translation>--path-frames: ganze Zahl von 2 bis 10000 erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--out: empty folder name</source>
        <translation>--out: leerer Ordnername</translation>
    </message>
    <message>
        <source>--budget: expected N (max error N/255) or psnr:DB, got &apos;%1&apos;</source>
        <translation>--budget: N (max. Fehler N/255) oder psnr:DB erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--size: expected WxH with 16..8192 pixels per side, got &apos;%1&apos;</source>
        <translation>--size: WxH mit 16..8192 Pixeln pro Seite erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--frames: expected a whole number from %1 to 10000, got &apos;%2&apos;</source>
        <translation>--frames: ganze Zahl von %1 bis 10000 erwartet, erhalten: &apos;%2&apos;</translation>
    </message>
    <message>
        <source>--lights: expected counts 1..%1 and/or &apos;scene&apos;, comma separated, got &apos;%2&apos;</source>
        <translation>--lights: Anzahlen 1..%1 und/oder &apos;scene&apos;, durch Kommas getrennt, erwartet, erhalten: &apos;%2&apos;</translation>
    </message>
    <message>
        <source>--methods: expected names from flat, gouraud, faceted, blinn-phong, phong, got &apos;%1&apos;</source>
        <translation>--methods: Namen aus flat, gouraud, faceted, blinn-phong, phong erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--details: expected fractions in (0, 1], comma separated, got &apos;%1&apos;</source>
        <translation>--details: Anteile in (0, 1], durch Kommas getrennt, erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>

Measures every shading method at every level of detail under 1, 4 and 8 lights (and the
scene&apos;s own lights): frame time against the error from the CPU double-precision reference.

  --scene FILE     a scene to measure (repeatable); default: the shipped default (tree and
                   cloud), sphere, torus and grazing scenes (--quick: default and sphere)
  --quick          400x300 px, detail 100/12.5/1.6 %: about 20 s on two cores
  --out DIR        where results.csv, fit.csv, chart.png and chart.svg go (default ./phonglab-bench)
  --budget SPEC    error budget for the fit: N (max error N/255, default 2) or psnr:DB
  --size WxH       frame size (default 800x600, --quick 400x300)
  --frames N       timed frames per configuration after 3 warm-up frames, at least 20 (default 20)
  --lights LIST    light counts, comma separated, 1..8, and/or &apos;scene&apos; (default 1,4,8,scene)
  --methods LIST   shading methods, comma separated (default flat,gouraud,faceted,blinn-phong,phong)
  --details LIST   detail fractions in (0, 1], comma separated, e.g. 1,0.25,0.0625
  --images         also write render | reference | error pictures into DIR/images
  --from CSV       measure nothing: fit and chart the rows of an earlier results.csv (e.g.
                   against another --budget); writes fit.csv and the chart into DIR
  --normals        the normal-method study (DIR/normals.csv, normals.png/svg) in a --quick run
                   too (a full run always has it)
  --path SPEC      instead of the sweep: draw each scene along a camera path with auto detail and
                   unseen lights left out, every frame against the reference; SPEC is orbit (one
                   turn moving out to 2.5x), dolly (from just outside the scene to 32x away) or a
                   keyframe file (docs/speed-vs-accuracy.md). Prints &apos;frames over budget: K of N&apos;;
                   writes DIR/path.csv and DIR/path.png/svg. Default scenes: default and sphere;
                   400x300 px, 10 timed frames per path frame
  --path-frames N  frames of an orbit or dolly, 2..10000 (default 24)

Frame time is the median wall time of render + glFinish (on llvmpipe a timer query misses the
rasterizer threads); gpu_ms in results.csv is GL_TIME_ELAPSED on real GPUs. Errors are in 8-bit
steps, more than 2 px from a silhouette (the outline and every occluding contour). Blinn-Phong
uses the matched exponent 4n (n = the material&apos;s shininess), as shaders/blinn-phong.frag does.

Exit status: 0 success, 1 a scene failed to load or render, 2 wrong arguments.</source>
        <translation>

Misst jedes Schattierungsverfahren in jeder Detailstufe unter 1, 4 und 8 Lichtquellen (und den
eigenen Lichtquellen der Szene): Framezeit gegenüber dem Fehler zur CPU-Referenz in doppelter
Genauigkeit.

  --scene FILE     eine zu messende Szene (wiederholbar); Standard: die mitgelieferten Szenen default
                   (Baum und Wolke), sphere, torus und grazing (--quick: default und sphere)
  --quick          400x300 px, Detailstufen 100/12,5/1,6 %: etwa 20 s auf zwei Kernen
  --out DIR        Ordner für results.csv, fit.csv, chart.png und chart.svg (Standard ./phonglab-bench)
  --budget SPEC    Fehlerbudget für die Anpassung: N (max. Fehler N/255, Standard 2) oder psnr:DB
  --size WxH       Bildgröße (Standard 800x600, --quick 400x300)
  --frames N       gemessene Frames pro Konfiguration nach 3 Aufwärm-Frames, mindestens 20 (Standard 20)
  --lights LIST    Anzahlen der Lichtquellen, durch Kommas getrennt, 1..8, und/oder &apos;scene&apos;
                   (Standard 1,4,8,scene)
  --methods LIST   Schattierungsverfahren, durch Kommas getrennt
                   (Standard flat,gouraud,faceted,blinn-phong,phong)
  --details LIST   Anteile der Detailstufen in (0, 1], durch Kommas getrennt, z. B. 1,0.25,0.0625
  --images         zusätzlich Bilder Render | Referenz | Fehler nach DIR/images schreiben
  --from CSV       nichts messen: die Zeilen einer früheren results.csv anpassen und als Diagramm
                   darstellen (z. B. mit einem anderen --budget); schreibt fit.csv und das Diagramm
                   nach DIR
  --normals        die Studie der Normalenverfahren (DIR/normals.csv, normals.png/svg) auch bei einem
                   --quick-Lauf (ein vollständiger Lauf enthält sie immer)
  --path SPEC      statt der Messreihe: jede Szene entlang eines Kamerapfads zeichnen, mit automatischer
                   Detailstufe und ohne unsichtbare Lichtquellen, jeden Frame gegenüber der Referenz;
                   SPEC ist orbit (eine Umdrehung, die sich bis auf 2,5x entfernt), dolly (von knapp
                   außerhalb der Szene bis 32x so weit weg) oder eine Keyframe-Datei
                   (docs/speed-vs-accuracy.md). Gibt &apos;frames over budget: K of N&apos; aus; schreibt
                   DIR/path.csv und DIR/path.png/svg. Standardszenen: default und sphere;
                   400x300 px, 10 gemessene Frames pro Pfad-Frame
  --path-frames N  Frames eines orbit oder dolly, 2..10000 (Standard 24)

Die Framezeit ist der Median der Echtzeit von Rendern + glFinish (auf llvmpipe verpasst eine
Timer-Abfrage die Rasterizer-Threads); gpu_ms in results.csv ist GL_TIME_ELAPSED auf echten GPUs.
Fehler sind in 8-Bit-Stufen angegeben, mehr als 2 px von einer Silhouette entfernt (dem Umriss und
jeder verdeckenden Kontur). Blinn-Phong verwendet den entsprechenden Exponenten 4n (n = der
Glanzexponent des Materials), wie es shaders/blinn-phong.frag tut.

Exit-Code: 0 Erfolg, 1 eine Szene konnte nicht geladen oder gerendert werden, 2 falsche Argumente.</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::BenchCommand</name>
    <message>
        <source>
fit to budget (%1, the scene&apos;s own lights, %2 px silhouette band left out):</source>
        <translation>
Anpassung an das Budget (%1, die eigenen Lichtquellen der Szene, %2 px Silhouettenrand ausgelassen):</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1: Lesen nicht möglich: %2</translation>
    </message>
    <message>
        <source>phonglab bench --path %1: %2 scene(s), %3x%4 px, %5 timed frames per path frame, budget %6, GL: %7</source>
        <translation>phonglab bench --path %1: %2 Szene(n), %3x%4 px, %5 gemessene Frames pro Pfad-Frame, Budget %6, GL: %7</translation>
    </message>
    <message>
        <source>every object at &quot;detail&quot;: &quot;auto&quot; (%1 px, shading within %2 steps), lights left out below %2 steps; against the exact Phong image and the same frame at full detail with every light
</source>
        <translation>jedes Objekt mit &quot;detail&quot;: &quot;auto&quot; (%1 px, Schattierung innerhalb von %2 Stufen), Lichtquellen unter %2 Stufen weggelassen; verglichen mit dem exakten Phong-Bild und demselben Frame in voller Detailstufe mit allen Lichtquellen
</translation>
    </message>
    <message>
        <source>  %1 frame %2/%3: distance %4, levels %5, %6 triangles (full %7), %8 lights left out, max error %9/255%10 (full detail %13/255), %11 ms (full %12 ms)</source>
        <translation>  %1 Frame %2/%3: Abstand %4, Detailstufen %5, %6 Dreiecke (voll %7), %8 Lichtquellen weggelassen, max. Fehler %9/255%10 (volle Detailstufe %13/255), %11 ms (voll %12 ms)</translation>
    </message>
    <message>
        <source>%1, %2: %3 of %4 frames over budget (at full detail: %7); triangles %5 saved, time %6 saved against full detail</source>
        <translation>%1, %2: %3 von %4 Frames über dem Budget (in voller Detailstufe: %7); Dreiecke: %5 gespart, Zeit: %6 gespart gegenüber voller Detailstufe</translation>
    </message>
    <message>
        <source>over budget at full detail with every light: %1 of %2 (what the method itself misses; no model can do better there)</source>
        <translation>über dem Budget in voller Detailstufe mit allen Lichtquellen: %1 von %2 (was das Schattierungsverfahren selbst verfehlt; besser kann dort kein Modell sein)</translation>
    </message>
    <message>
        <source>triangles drawn: %1 against %2 at full detail (%3 saved); frame time: %4 ms against %5 ms (%6 saved), summed over the frames</source>
        <translation>gezeichnete Dreiecke: %1 gegenüber %2 in voller Detailstufe (%3 gespart); Framezeit: %4 ms gegenüber %5 ms (%6 gespart), summiert über die Frames</translation>
    </message>
    <message>
        <source>done in %1 s</source>
        <translation>fertig in %1 s</translation>
    </message>
    <message>
        <source>%1: cannot create the output folder</source>
        <translation>%1: der Ausgabeordner kann nicht erstellt werden</translation>
    </message>
    <message>
        <source>phonglab bench%1: %2 scene(s), %3x%4 px, %5 timed frames after %6 warm-up, GL: %7</source>
        <translation>phonglab bench%1: %2 Szene(n), %3x%4 px, %5 gemessene Frames nach %6 Aufwärm-Frames, GL: %7</translation>
    </message>
    <message>
        <source>frame ms = median wall time of render + glFinish; cpu ms = submission; errors in 8-bit steps against the CPU reference; hl = inside the specular highlight; * = the scene&apos;s own lights; blinn-phong uses the matched exponent 4n
</source>
        <translation>frame ms = Median der Echtzeit von Rendern + glFinish; cpu ms = Übergabe der Befehle; Fehler in 8-Bit-Stufen gegenüber der CPU-Referenz; hl = innerhalb des Glanzlichts; * = die eigenen Lichtquellen der Szene; blinn-phong verwendet den entsprechenden Exponenten 4n
</translation>
    </message>
    <message>
        <source>
per-object fit (%1; each object drawn alone for its time, its own pixels for its error):</source>
        <translation>
Anpassung pro Objekt (%1; jedes Objekt für seine Zeit allein gezeichnet, seine eigenen Pixel für seinen Fehler):</translation>
    </message>
    <message>
        <source>  %1: drawn whole: %2 ms, max %3/255, PSNR %4 dB (%5)</source>
        <translation>  %1: als Ganzes gezeichnet: %2 ms, max. %3/255, PSNR %4 dB (%5)</translation>
    </message>
    <message>
        <source>within budget</source>
        <translation>innerhalb des Budgets</translation>
    </message>
    <message>
        <source>  (--from draws nothing: the choices are not drawn whole to confirm them)</source>
        <translation>  (--from zeichnet nichts: die Auswahl wird nicht als Ganzes gezeichnet, um sie zu bestätigen)</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::CheckCommand</name>
    <message>
        <source>Show help.</source>
        <translation>Hilfe anzeigen.</translation>
    </message>
    <message>
        <source>Scene file (JSON).</source>
        <translation>Szenendatei (JSON).</translation>
    </message>
    <message>
        <source>missing the scene file</source>
        <translation>Szenendatei fehlt</translation>
    </message>
    <message>
        <source>exactly one scene file expected</source>
        <translation>genau eine Szenendatei erwartet</translation>
    </message>
    <message>
        <source>--equation: expected slide or guarded, got &apos;%1&apos;</source>
        <translation>--equation: slide oder guarded erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--tolerance: expected 0..255 8-bit steps, got &apos;%1&apos;</source>
        <translation>--tolerance: 0..255 8-Bit-Stufen erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--diff: missing the output file</source>
        <translation>--diff: Ausgabedatei fehlt</translation>
    </message>
    <message>
        <source>no reference: %1</source>
        <translation>keine Referenz: %1</translation>
    </message>
    <message>
        <source>--project takes both stages from the project; leave out --vertex and --fragment</source>
        <translation>--project nimmt beide Stufen aus dem Projekt; --vertex und --fragment weglassen</translation>
    </message>
    <message>
        <source>--program names a program of --project</source>
        <translation>--program nennt ein Programm von --project</translation>
    </message>
    <message>
        <source>program %1: %2 and %3</source>
        <translation>Programm %1: %2 und %3</translation>
    </message>
    <message>
        <source> with --program NAME</source>
        <translation> mit --program NAME</translation>
    </message>
    <message>
        <source>

Renders SCENE.json with the shaders `render` would use, compares the image with the exact
(double-precision) reference of the same scene, leaving out a band around silhouettes,
and when it differs names the classic mistake that explains it.

%1
  --project PATH      a WebGL project (a page, a script or a folder): its shaders are found in
                      script elements, textareas, JavaScript strings or files of their own,
                      and paired as its calls pair them
  --program NAME      which of the project&apos;s programs, where it has several that light
%2
  --tolerance STEPS   largest error allowed per channel, in 8-bit steps (0..255), default %3
%4
  --equation E        demand the slide&apos;s equation (slide: a highlight even where N·L &lt;= 0)
                      or the guarded one (guarded: none there); by default either passes
  --json              print one JSON object (keys: verdict, psnr_db, max_error, bad_fraction,
                      tolerance, worst, diagnosis, undetectable, errors, bindings, equation,
                      notes, warnings, together, partial, bindings_by_use, precision)
                      instead of text
  --diff OUT.png      write the error heatmap: dark green exact, bright green 1/255, yellow 4/255,
                      red 8/255 or more off; dark blue the silhouette band left out, black the
                      background

Mistake keys: %5, unknown.

Exit status: 0 matches, 1 does not match, does not compile, or bad input, 2 wrong arguments.
Compile errors are printed as FILE:LINE:COL: error: MESSAGE.</source>
        <extracomment>%1: the lines of --vertex and --fragment; %2: of --shading and --size; %4: of --bind, --define and --precision, each option&apos;s own</extracomment>
        <translation>

Rendert SCENE.json mit den Shadern, die `render` verwenden würde, vergleicht das Bild mit der
exakten Referenz (doppelte Genauigkeit) derselben Szene, ohne einen Rand um die Silhouetten,
und nennt bei einer Abweichung den typischen Fehler, der sie erklärt.

%1
  --project PATH      ein WebGL-Projekt (eine Seite, ein Skript oder ein Ordner): seine Shader
                      werden in script-Elementen, Textfeldern, JavaScript-Zeichenketten oder
                      eigenen Dateien gefunden und so gepaart, wie seine Aufrufe sie paaren
  --program NAME      welches der Programme des Projekts, wo mehrere beleuchten
%2
  --tolerance STEPS   größter erlaubter Fehler pro Kanal, in 8-Bit-Stufen (0..255), Standard %3
%4
  --equation E        die Gleichung der Folie verlangen (slide: ein Glanzlicht auch dort, wo
                      N·L &lt;= 0) oder die abgesicherte (guarded: dort keines); standardmäßig
                      besteht beides
  --json              ein JSON-Objekt statt Text ausgeben (Schlüssel: verdict, psnr_db, max_error,
                      bad_fraction, tolerance, worst, diagnosis, undetectable, errors, bindings,
                      equation, notes, warnings, together, partial, bindings_by_use,
                      precision)
  --diff OUT.png      die Fehler-Heatmap schreiben: dunkelgrün exakt, hellgrün 1/255, gelb 4/255,
                      rot ab 8/255 Abweichung; dunkelblau der ausgelassene Silhouettenrand,
                      schwarz der Hintergrund

Fehlerschlüssel: %5, unknown.

Exit-Code: 0 stimmt überein, 1 stimmt nicht überein, kompiliert nicht oder ungültige Eingabe,
2 falsche Argumente.
Kompilierfehler werden als FILE:LINE:COL: error: MESSAGE ausgegeben.</translation>
    </message>
    <message>
        <source>usage: phonglab check SCENE.json [--vertex FILE] [--fragment FILE] [--shading NAME] [--size WxH]
                      [--project PATH [--program NAME]]
                      [--tolerance STEPS] [--bind NAME=MEANING ...] [--equation slide|guarded]
                      [--define NAME=VALUE ...] [--precision highp|as-written]
                      [--json] [--diff OUT.png]
       phonglab check [SCENE.json] --page PROJECT [--page-file FILE] [--library DIR ...]
                      [--url-map PREFIX=PATH ...] [--page-step STEP ...] [--page-frame N]
                      [--page-timeout S] [--meshes DIR] [--page-out DIR] [--json]
       phonglab check [SCENE.json] --capture capture.json [--meshes DIR] [--json]</source>
        <translation>Aufruf: phonglab check SCENE.json [--vertex FILE] [--fragment FILE] [--shading NAME] [--size WxH]
                       [--project PATH [--program NAME]]
                       [--tolerance STEPS] [--bind NAME=MEANING ...] [--equation slide|guarded]
                       [--define NAME=VALUE ...] [--precision highp|as-written]
                       [--json] [--diff OUT.png]
       phonglab check [SCENE.json] --page PROJECT [--page-file FILE] [--library DIR ...]
                       [--url-map PREFIX=PATH ...] [--page-step STEP ...] [--page-frame N]
                       [--page-timeout S] [--meshes DIR] [--page-out DIR] [--json]
       phonglab check [SCENE.json] --capture capture.json [--meshes DIR] [--json]</translation>
    </message>
    <message>
        <source>--project reads the shaders from the files, --page takes them from the browser: give one</source>
        <translation>--project liest die Shader aus den Dateien, --page nimmt sie aus dem Browser: eines angeben</translation>
    </message>
    <message>
        <source>--page takes both stages from the browser; leave out --vertex and --fragment</source>
        <translation>--page nimmt beide Stufen aus dem Browser; --vertex und --fragment weglassen</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::CheckSteps</name>
    <message>
        <source>the shaders did not compile</source>
        <translation>die Shader ließen sich nicht kompilieren</translation>
    </message>
    <message>
        <source>rendering failed</source>
        <translation>Rendern fehlgeschlagen</translation>
    </message>
    <message>
        <source>cannot read shader: %1</source>
        <translation>Shader kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>nothing to compare: no surface away from silhouettes in this view at %1x%2</source>
        <translation>nichts zu vergleichen: keine Oberfläche abseits der Silhouetten in dieser Ansicht bei %1x%2</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::ClassFolder</name>
    <message>
        <source>%1 files for the %2 stage: %3 (keep one)</source>
        <translation>%1 Dateien für die Stufe %2: %3 (nur eine behalten)</translation>
    </message>
    <message>
        <source>no shader file (.vert, .frag, .vs, .fs, .glsl) in %1</source>
        <translation>keine Shader-Datei (.vert, .frag, .vs, .fs, .glsl) in %1</translation>
    </message>
    <message>
        <source>%1: no such folder</source>
        <translation>%1: Ordner existiert nicht</translation>
    </message>
    <message>
        <source>%1: not a folder (one subfolder per submission expected)</source>
        <translation>%1: kein Ordner (ein Unterordner pro Abgabe erwartet)</translation>
    </message>
    <message>
        <source>%1: no submission folders in it (one subfolder per student expected)</source>
        <translation>%1: enthält keine Abgabeordner (ein Unterordner pro Person erwartet)</translation>
    </message>
    <message>
        <source>not read: %1 (a symbolic link, or a path that leaves the submission; hand in the file itself)</source>
        <translation>nicht gelesen: %1 (ein symbolischer Link oder ein Pfad, der die Abgabe verlässt; die Datei selbst abgeben)</translation>
    </message>
    <message>
        <source>no program that lights anything (%1)</source>
        <translation>kein Programm, das etwas beleuchtet (%1)</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::ClassStaging</name>
    <message>
        <source>%1: cannot regroup the files into %2</source>
        <translation>%1: die Dateien können nicht nach %2 umsortiert werden</translation>
    </message>
    <message>
        <source>%1: cannot copy it into %2</source>
        <translation>%1: kann nicht nach %2 kopiert werden</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::Cli</name>
    <message>
        <source>
&apos;phonglab &lt;command&gt; --help&apos; describes a command&apos;s options.</source>
        <translation>
&apos;phonglab &lt;command&gt; --help&apos; beschreibt die Optionen eines Befehls.</translation>
    </message>
    <message>
        <source>
--lang en|de on any command or the window chooses the language of that run (else the locale&apos;s: LANGUAGE, LC_ALL, LC_MESSAGES, LANG).</source>
        <translation>
--lang en|de wählt bei jedem Befehl und im Fenster die Sprache dieses Aufrufs (sonst die des Gebietsschemas: LANGUAGE, LC_ALL, LC_MESSAGES, LANG).</translation>
    </message>
    <message>
        <source>measure speed against accuracy of every shading method and detail</source>
        <translation>Geschwindigkeit gegen Genauigkeit jedes Schattierungsverfahrens und jeder Detailstufe messen</translation>
    </message>
    <message>
        <source>render a scene offscreen into a PNG</source>
        <translation>eine Szene ohne Fenster in ein PNG rendern</translation>
    </message>
    <message>
        <source>check a shader against the exact image and name the mistake that explains a wrong one</source>
        <translation>einen Shader am exakten Bild prüfen und den Fehler benennen, der ein falsches Bild erklärt</translation>
    </message>
    <message>
        <source>check a class folder of submissions, each in a process of its own; a report</source>
        <translation>einen Ordner mit den Abgaben einer Gruppe prüfen, jede in einem eigenen Prozess; mit Bericht</translation>
    </message>
    <message>
        <source>load a mesh and report its size, normals, bounds and warnings</source>
        <translation>ein Mesh laden und Größe, Normalen, Ausdehnung und Warnungen ausgeben</translation>
    </message>
    <message>
        <source>

commands:
</source>
        <translation>

Befehle:
</translation>
    </message>
    <message>
        <source>
&apos;phonglab --version&apos; prints the version.</source>
        <translation>
&apos;phonglab --version&apos; gibt die Version aus.</translation>
    </message>
    <message>
        <source>%1: no such file, and not a command</source>
        <translation>%1: keine solche Datei und kein Befehl</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::CliCommon</name>
    <message>
        <source>%1 given more than once (&apos;%2&apos;, then &apos;%3&apos;): give it once</source>
        <translation>%1 mehrfach angegeben (&apos;%2&apos;, dann &apos;%3&apos;): nur einmal angeben</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::CoursePlatformOutputs</name>
    <message>
        <source>%1: matches the exact image.</source>
        <translation>%1: stimmt mit dem exakten Bild überein.</translation>
    </message>
    <message>
        <source>%1: differs from the exact image; no classic mistake explains it.</source>
        <translation>%1: weicht vom exakten Bild ab; kein typischer Fehler erklärt es.</translation>
    </message>
    <message>
        <source>%1: differs from the exact image, most likely %2.</source>
        <translation>%1: weicht vom exakten Bild ab, wahrscheinlich %2.</translation>
    </message>
    <message>
        <source>%1: not checked, %2 line %3: %4</source>
        <translation>%1: nicht geprüft, %2 Zeile %3: %4</translation>
    </message>
    <message>
        <source>%1: not checked: %2</source>
        <translation>%1: nicht geprüft: %2</translation>
    </message>
    <message>
        <source>%1: took longer than the time allowed.</source>
        <translation>%1: hat länger gedauert als erlaubt.</translation>
    </message>
    <message>
        <source>%1: the check crashed or ran out of memory.</source>
        <translation>%1: die Prüfung ist abgestürzt oder hatte nicht genug Speicher.</translation>
    </message>
    <message>
        <source>--points: expected VERDICT=NUMBER, … with the verdicts pass, fail, error, timeout, crash; got &apos;%1&apos;</source>
        <translation>--points: erwartet URTEIL=ZAHL, … mit den Urteilen pass, fail, error, timeout, crash; erhalten &apos;%1&apos;</translation>
    </message>
    <message>
        <source>%1: cannot write: %2</source>
        <translation>%1: kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::GradeCommand</name>
    <message>
        <source>Show help.</source>
        <translation>Hilfe anzeigen.</translation>
    </message>
    <message>
        <source>missing the submissions folder</source>
        <translation>der Ordner mit den Abgaben fehlt</translation>
    </message>
    <message>
        <source>exactly one submissions folder expected</source>
        <translation>genau ein Abgabenordner erwartet</translation>
    </message>
    <message>
        <source>--scene: at least one scene expected</source>
        <translation>--scene: mindestens eine Szene erwartet</translation>
    </message>
    <message>
        <source>--out: missing the folder</source>
        <translation>--out: der Ordner fehlt</translation>
    </message>
    <message>
        <source>--equation: expected slide or guarded, got &apos;%1&apos;</source>
        <translation>--equation: slide oder guarded erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--tolerance: expected 0..255 8-bit steps, got &apos;%1&apos;</source>
        <translation>--tolerance: 0..255 8-Bit-Stufen erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--timeout: expected seconds in (0, 86400], got &apos;%1&apos;</source>
        <translation>--timeout: Sekunden in (0, 86400] erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>%1: cannot make the folder</source>
        <translation>%1: Ordner kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>%1: cannot write into it: %2</source>
        <translation>%1: kann nicht beschrieben werden: %2</translation>
    </message>
    <message>
        <source>cannot find the phonglab program to run the checks with (set PHONGLAB_EXE)</source>
        <translation>das phonglab-Programm zum Ausführen der Prüfungen wurde nicht gefunden (PHONGLAB_EXE setzen)</translation>
    </message>
    <message>
        <source>grade: kept %1 finished checks of the stopped run</source>
        <translation>grade: %1 fertige Prüfungen des abgebrochenen Laufs behalten</translation>
    </message>
    <message>
        <source>no program named %1 (there are: %2)</source>
        <translation>kein Programm namens %1 (vorhanden: %2)</translation>
    </message>
    <message>
        <source>--jobs: expected 1..256, got &apos;%1&apos;</source>
        <translation>--jobs: 1..256 erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--memory: expected 64..1048576 MiB, got &apos;%1&apos;</source>
        <translation>--memory: 64..1048576 MiB erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>grade: %1 checks; %2</source>
        <translation>grade: %1 Prüfungen; %2</translation>
    </message>
    <message>
        <source>usage: phonglab grade SUBMISSIONS --scene FILE [--scene FILE ...] [--out DIR]
                      [--jobs N] [--timeout SECONDS] [--memory MIB] [--size WxH]
                      [--tolerance STEPS] [--bind NAME=MEANING ...] [--equation slide|guarded]
                      [--define NAME=VALUE ...] [--precision highp|as-written]
                      [--points pass=N,fail=N,error=N,timeout=N,crash=N] [--resume]
                      [--program NAME]
                      [--pages [--library DIR ...] [--url-map PREFIX=PATH ...] [--page-step STEP ...]
                       [--page-frame N] [--page-timeout S] [--meshes DIR]]</source>
        <translation>Aufruf: phonglab grade SUBMISSIONS --scene FILE [--scene FILE ...] [--out DIR]
                       [--jobs N] [--timeout SECONDS] [--memory MIB] [--size WxH]
                       [--tolerance STEPS] [--bind NAME=MEANING ...] [--equation slide|guarded]
                       [--define NAME=VALUE ...] [--precision highp|as-written]
                       [--points pass=N,fail=N,error=N,timeout=N,crash=N] [--resume]
                       [--program NAME]
                       [--pages [--library DIR ...] [--url-map PREFIX=PATH ...] [--page-step STEP ...]
                        [--page-frame N] [--page-timeout S] [--meshes DIR]]</translation>
    </message>
    <message>
        <source>

Checks every submission in SUBMISSIONS against every scene, as `phonglab check` does,
and writes what each student got into DIR. Each subfolder of SUBMISSIONS is one
submission: its vertex and/or fragment shader, under any file names (.vert .vs .vsh,
.frag .fs .fsh; .glsl by whether it writes gl_Position), in any dialect `check` takes,
or a WebGL project (pages and scripts, as check --project reads them; each program
that lights is checked on its own). SUBMISSIONS may be a .zip or .tar.gz, and a
course platform&apos;s download: Moodle&apos;s folders or flat files by student. A student&apos;s
own archive is unpacked once; an archive with links or names that leave it is
refused. A stage left out is the scene&apos;s shading method&apos;s shipped one. Each check
runs in a child process of its own: a shader that runs too long or crashes costs
that one verdict.

  --scene FILE        a scene to check with; repeatable, at least one
  --out DIR           where the results go, default ./grades
  --jobs N            checks at once, default the number of cores (%1)
  --timeout SECONDS   wall-clock limit of one check, default %2
  --memory MIB        memory limit of one check, default %3
%4
  --tolerance STEPS   largest error allowed per channel (0..255), default %5
%6
  --equation E        demand the slide&apos;s (slide) or the guarded (guarded) equation
  --points P          what each verdict is worth in moodle-grades.csv, summed over a
                      student&apos;s rows; default pass=1,fail=0,error=0,timeout=0,crash=0
  --resume            keep the rows a stopped run of the same command finished
  --program NAME      of a WebGL project with several programs, only this one

Writes DIR/grades.csv (columns submission, scene, verdict, psnr_db, max_error,
bad_fraction, key, also, file, line, equation, bindings, seconds, mistakes, program,
student, participant, page_fidelity, page_javascript, page_error), DIR/grades.json
(the check&apos;s JSON per row), DIR/report.html and its DIR/images/, and a table on stdout. From Moodle also DIR/moodle-grades.csv
(its offline grading worksheet) and DIR/feedback.zip (a feedback.html per student).
Verdicts: pass, fail, error, timeout, crash.

Exit status: 0 every submission got a verdict, 1 the run could not complete (a scene
that does not load, no submissions, DIR not writable), 2 wrong arguments.</source>
        <extracomment>%4: the line of --size; %6: of --bind, --define and --precision, each option&apos;s own</extracomment>
        <translation>

Prüft jede Abgabe in SUBMISSIONS mit jeder Szene, wie `phonglab check` es tut, und
schreibt die Ergebnisse der Studierenden nach DIR. Jeder Unterordner von SUBMISSIONS ist
eine Abgabe: ihr Vertex- und/oder Fragment-Shader, unter beliebigen Dateinamen (.vert .vs
.vsh, .frag .fs .fsh; .glsl je nachdem, ob gl_Position geschrieben wird), in jedem Dialekt,
den `check` annimmt, oder ein WebGL-Projekt (Seiten und Skripte, wie check --project sie
liest; jedes Programm, das beleuchtet, wird für sich beurteilt). SUBMISSIONS darf eine .zip-
oder .tar.gz-Datei sein, auch der Download einer Lernplattform: Moodles Ordner oder flache
Dateien pro Person. Ein eigenes Archiv einer Person wird einmal entpackt; ein Archiv mit
Links oder Namen, die es verlassen, wird abgelehnt. Für eine fehlende Stufe wird die
mitgelieferte des Schattierungsverfahrens der Szene verwendet. Jede Prüfung läuft in einem
eigenen Kindprozess: Ein Shader, der zu lange läuft oder abstürzt, kostet nur dieses eine
Urteil.

  --scene FILE        eine Szene, mit der geprüft wird; wiederholbar, mindestens eine
  --out DIR           Ordner für die Ergebnisse, Standard ./grades
  --jobs N            gleichzeitige Prüfungen, Standard die Anzahl der Kerne (%1)
  --timeout SECONDS   Zeitlimit (Echtzeit) einer Prüfung, Standard %2
  --memory MIB        Speicherlimit einer Prüfung, Standard %3
%4
  --tolerance STEPS   größter erlaubter Fehler pro Kanal (0..255), Standard %5
%6
  --equation E        die Gleichung der Folie (slide) oder die abgesicherte (guarded) verlangen
  --points P          was jedes Urteil in moodle-grades.csv wert ist, summiert über die
                      Zeilen einer Person; Standard pass=1,fail=0,error=0,timeout=0,crash=0
  --resume            die Zeilen behalten, die ein abgebrochener Lauf desselben Befehls
                      fertig hatte
  --program NAME      von einem WebGL-Projekt mit mehreren Programmen nur dieses

Schreibt DIR/grades.csv (Spalten submission, scene, verdict, psnr_db, max_error,
bad_fraction, key, also, file, line, equation, bindings, seconds, mistakes, program,
student, participant, page_fidelity, page_javascript, page_error), DIR/grades.json
(das JSON der Prüfung pro Zeile), DIR/report.html mit DIR/images/ sowie eine Tabelle auf stdout. Aus Moodle außerdem DIR/moodle-grades.csv
(seine Offline-Bewertungstabelle) und DIR/feedback.zip (eine feedback.html pro Person).
Urteile: pass, fail, error, timeout, crash.

Exit-Code: 0 jede Abgabe hat ein Urteil erhalten, 1 der Lauf konnte nicht abgeschlossen
werden (eine Szene lädt nicht, keine Abgaben, DIR nicht beschreibbar), 2 falsche Argumente.</translation>
    </message>
    <message>
        <source>

With --pages each submission&apos;s page runs in headless Chromium, as check --page runs it,
once per project (its capture and frames in DIR/pages/NAME/); the course scenes are then
checked with the program and the values the page used.
</source>
        <translation>

Mit --pages läuft die Seite jeder Abgabe in headless Chromium, wie check --page sie ausführt,
einmal je Projekt (Aufzeichnung und Bilder in DIR/pages/NAME/); die Kursszenen werden dann
mit dem Programm und den Werten geprüft, die die Seite verwendet hat.
</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::GradePages</name>
    <message>
        <source>grade: page %1 of %2 run</source>
        <translation>grade: Seite %1 von %2 ausgeführt</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::GradeReferences</name>
    <message>
        <source>%1: no exact image: %2</source>
        <translation>%1: kein exaktes Bild: %2</translation>
    </message>
    <message>
        <source>grade: the exact image of %1, %2 %</source>
        <translation>grade: das exakte Bild von %1, %2 %</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::GradeReport</name>
    <message>
        <source>Passes per scene</source>
        <translation>Bestanden je Szene</translation>
    </message>
    <message>
        <source>%1 of %2 pass</source>
        <translation>%1 von %2 bestanden</translation>
    </message>
    <message>
        <source>Most common mistakes</source>
        <translation>Häufigste Fehler</translation>
    </message>
    <message>
        <source>None: no check failed.</source>
        <translation>Keine: keine Prüfung ist fehlgeschlagen.</translation>
    </message>
    <message>
        <source>Matches the exact image.</source>
        <translation>Stimmt mit dem exakten Bild überein.</translation>
    </message>
    <message>
        <source>no classic mistake explains the difference; the heatmap shows where it is.</source>
        <translation>kein typischer Fehler erklärt den Unterschied; die Heatmap zeigt, wo er liegt.</translation>
    </message>
    <message>
        <source>%1 explains %2 % of the difference: %3</source>
        <translation>%1 erklärt %2 % des Unterschieds: %3</translation>
    </message>
    <message>
        <source>note:</source>
        <translation>Hinweis:</translation>
    </message>
    <message>
        <source>theirs</source>
        <translation>Abgabe</translation>
    </message>
    <message>
        <source>exact</source>
        <translation>exakt</translation>
    </message>
    <message>
        <source>heatmap</source>
        <translation>Heatmap</translation>
    </message>
    <message>
        <source>opens it in the window</source>
        <translation>öffnet sie im Fenster</translation>
    </message>
    <message>
        <source>PhongLab grades: %1</source>
        <translation>PhongLab-Bewertung: %1</translation>
    </message>
    <message>
        <source>%1 submission</source>
        <translation>%1 Abgabe</translation>
    </message>
    <message>
        <source>%1 submissions</source>
        <translation>%1 Abgaben</translation>
    </message>
    <message>
        <source>%1 scene</source>
        <translation>%1 Szene</translation>
    </message>
    <message>
        <source>%1 scenes</source>
        <translation>%1 Szenen</translation>
    </message>
    <message>
        <source>%1, %2×%3 pixels, tolerance %4/255. Sort the rows by a column&apos;s title.</source>
        <translation>%1, %2×%3 Pixel, Toleranz %4/255. Ein Klick auf einen Spaltentitel sortiert die Zeilen.</translation>
    </message>
    <message>
        <source>Every student and scene</source>
        <translation>Alle Abgaben und Szenen</translation>
    </message>
    <message>
        <source>student</source>
        <translation>Abgabe</translation>
    </message>
    <message>
        <source>scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>verdict</source>
        <translation>Urteil</translation>
    </message>
    <message>
        <source>images</source>
        <translation>Bilder</translation>
    </message>
    <message>
        <source>why, and the command that opens it</source>
        <translation>Begründung und der Befehl, der sie öffnet</translation>
    </message>
    <message>
        <source>%1 mistakes together explain %2 % of the difference:</source>
        <translation>%1 Fehler zusammen erklären %2 % des Unterschieds:</translation>
    </message>
    <message>
        <source>warning:</source>
        <translation>Warnung:</translation>
    </message>
    <message>
        <source>the browser&apos;s</source>
        <translation>im Browser</translation>
    </message>
    <message>
        <source>drawn again</source>
        <translation>erneut gezeichnet</translation>
    </message>
    <message>
        <source>difference</source>
        <translation>Differenz</translation>
    </message>
    <message>
        <source>The page was not run: %1</source>
        <translation>Die Seite wurde nicht ausgeführt: %1</translation>
    </message>
    <message>
        <source>PhongLab does not draw this page as the browser did (largest difference %1): its findings may be PhongLab&apos;s mistake.</source>
        <translation>PhongLab zeichnet diese Seite nicht so, wie der Browser es tat (größte Abweichung %1): die Befunde können PhongLabs Fehler sein.</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::GradeRowCheck</name>
    <message>
        <source>no reference: %1</source>
        <translation>keine Referenz: %1</translation>
    </message>
    <message>
        <source>the check drew no image (%1)</source>
        <translation>die Prüfung hat kein Bild gezeichnet (%1)</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::GradeRun</name>
    <message>
        <source>grade: %1 of %2 checked</source>
        <translation>grade: %1 von %2 geprüft</translation>
    </message>
    <message>
        <source>, about %1 s left</source>
        <translation>, noch etwa %1 s</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::GradeTables</name>
    <message>
        <source>student</source>
        <translation>Abgabe</translation>
    </message>
    <message>
        <source>scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>verdict</source>
        <translation>Urteil</translation>
    </message>
    <message>
        <source>PSNR dB</source>
        <translation>PSNR dB</translation>
    </message>
    <message>
        <source>mistake, where</source>
        <translation>Fehler, Stelle</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::GradedChild</name>
    <message>
        <source>the check could not start: %1</source>
        <translation>die Prüfung konnte nicht gestartet werden: %1</translation>
    </message>
    <message>
        <source>ran past the %1 s limit and was stopped (a loop that runs too long, or a frame the GPU cannot finish)</source>
        <translation>hat das Zeitlimit von %1 s überschritten und wurde abgebrochen (eine zu lange laufende Schleife oder ein Frame, den die GPU nicht fertigstellen kann)</translation>
    </message>
    <message>
        <source>used more than %1 MiB of memory and was stopped</source>
        <translation>hat mehr als %1 MiB Speicher belegt und wurde beendet</translation>
    </message>
    <message>
        <source>the check crashed with signal %1 (%2)</source>
        <translation>die Prüfung ist mit Signal %1 (%2) abgestürzt</translation>
    </message>
    <message>
        <source>; it said: </source>
        <translation>; Ausgabe: </translation>
    </message>
    <message>
        <source>the check ran out of memory</source>
        <translation>der Prüfung ging der Speicher aus</translation>
    </message>
    <message>
        <source>the check exited with status %1 without an answer</source>
        <translation>die Prüfung wurde mit Exit-Code %1 ohne Antwort beendet</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::ImportMeshCommand</name>
    <message>
        <source>__import-mesh is internal: the app runs it to import a mesh file</source>
        <translation>__import-mesh ist intern: das Programm ruft es auf, um eine Mesh-Datei zu importieren</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::MeshInfoCommand</name>
    <message>
        <source>Show help.</source>
        <translation>Hilfe anzeigen.</translation>
    </message>
    <message>
        <source>Normal method.</source>
        <translation>Verfahren für die Normalen.</translation>
    </message>
    <message>
        <source>Crease angle.</source>
        <translation>Knickwinkel.</translation>
    </message>
    <message>
        <source>expected exactly one mesh file</source>
        <translation>genau eine Mesh-Datei erwartet</translation>
    </message>
    <message>
        <source>--normals: unknown method &apos;%1&apos; (known: %2)</source>
        <translation>--normals: unbekanntes Verfahren &apos;%1&apos; (bekannt: %2)</translation>
    </message>
    <message>
        <source>--crease: expected degrees in [0, 180], got &apos;%1&apos;</source>
        <translation>--crease: Grad in [0, 180] erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>from the file, per face corner</source>
        <translation>aus der Datei, pro Flächenecke</translation>
    </message>
    <message>
        <source>computed (%1)</source>
        <translation>berechnet (%1)</translation>
    </message>
    <message>
        <source>gpu vertices:    %1 (%2 split for differing normals)</source>
        <translation>GPU-Vertices:    %1 (%2 wegen unterschiedlicher Normalen aufgeteilt)</translation>
    </message>
    <message>
        <source>load time:       %1 ms%2</source>
        <translation>Ladezeit:        %1 ms%2</translation>
    </message>
    <message>
        <source> (from the mesh cache)</source>
        <translation> (aus dem Mesh-Cache)</translation>
    </message>
    <message>
        <source>file:            %1</source>
        <translation>Datei:           %1</translation>
    </message>
    <message>
        <source>vertices:        %1</source>
        <translation>Vertices:        %1</translation>
    </message>
    <message>
        <source>faces:           %1</source>
        <translation>Flächen:         %1</translation>
    </message>
    <message>
        <source>triangles:       %1</source>
        <translation>Dreiecke:        %1</translation>
    </message>
    <message>
        <source>analytic</source>
        <translation>analytisch</translation>
    </message>
    <message>
        <source>normals:         %1</source>
        <translation>Normalen:        %1</translation>
    </message>
    <message>
        <source>bounds:          %1 .. %2</source>
        <translation>Ausdehnung:      %1 .. %2</translation>
    </message>
    <message>
        <source>surface:         %1</source>
        <translation>Oberfläche:      %1</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>geschlossen</translation>
    </message>
    <message>
        <source>open</source>
        <translation>offen</translation>
    </message>
    <message>
        <source>warnings:        %1</source>
        <translation>Warnungen:       %1</translation>
    </message>
    <message>
        <source>

Loads a mesh (OBJ, PLY, OFF, STL, OM) the way a scene does and prints its vertices,
faces, where the normals came from, bounds, split vertices, warnings and load time.

  --json            machine-readable output; keys: vertices, faces, normals (&quot;file&quot; or
                    &quot;computed&quot;), normal_method, bounds, warnings, load_ms, and more
  --normals METHOD  auto (default: the file&apos;s, else angle), flat, average, area, angle
  --crease DEG      split computed normals where faces meet at more than DEG degrees; a file&apos;s
                    own normals are used as written (--normals angle computes them instead)

Exit status: 0 loaded (maybe with warnings), 1 cannot be loaded, 2 wrong arguments.</source>
        <translation>

Lädt ein Mesh (OBJ, PLY, OFF, STL, OM) so, wie eine Szene es lädt, und gibt seine Vertices,
Flächen, die Herkunft der Normalen, Ausdehnung, aufgeteilte Vertices, Warnungen und Ladezeit aus.

  --json            maschinenlesbare Ausgabe; Schlüssel: vertices, faces, normals (&quot;file&quot; oder
                    &quot;computed&quot;), normal_method, bounds, warnings, load_ms und weitere
  --normals METHOD  auto (Standard: die der Datei, sonst angle), flat, average, area, angle
  --crease DEG      berechnete Normalen aufteilen, wo Flächen in einem Winkel von mehr als DEG Grad
                    aufeinandertreffen; eigene Normalen einer Datei bleiben, wie sie sind
                    (--normals angle berechnet sie stattdessen)

Exit-Code: 0 geladen (eventuell mit Warnungen), 1 kann nicht geladen werden, 2 falsche Argumente.</translation>
    </message>
    <message>
        <source>--crease %1 is not used: the file has normals of its own, used as written (--normals angle computes them with the crease)</source>
        <translation>--crease %1 wird nicht verwendet: die Datei hat eigene Normalen, die unverändert verwendet werden (--normals angle berechnet sie mit dem Knickwinkel)</translation>
    </message>
    <message>
        <source>Print JSON.</source>
        <translation>JSON ausgeben.</translation>
    </message>
    <message>
        <source>, crease %1°</source>
        <translation>, Knickwinkel %1°</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::PageOptions</name>
    <message>
        <source>run each submission&apos;s page in headless Chromium and check what it drew</source>
        <translation>die Seite jeder Abgabe in headless Chromium ausführen und prüfen, was sie gezeichnet hat</translation>
    </message>
    <message>
        <source>run the project&apos;s page in headless Chromium and check what it drew</source>
        <translation>die Seite des Projekts in headless Chromium ausführen und prüfen, was sie gezeichnet hat</translation>
    </message>
    <message>
        <source>which page of the project, default index.html or its only page</source>
        <translation>welche Seite des Projekts, Vorgabe index.html oder seine einzige Seite</translation>
    </message>
    <message>
        <source>a folder of the course&apos;s starter files the page loads (Common/, webgl-utils, gl-matrix); repeatable</source>
        <translation>ein Ordner mit den Vorlagedateien des Kurses, die die Seite lädt (Common/, webgl-utils, gl-matrix); wiederholbar</translation>
    </message>
    <message>
        <source>answer an outside address (a CDN&apos;s link) from a local file or folder; repeatable</source>
        <translation>eine externe Adresse (den Link eines CDN) aus einer lokalen Datei oder einem Ordner beantworten; wiederholbar</translation>
    </message>
    <message>
        <source>what a student does before looking: &apos;click SELECTOR&apos;, &apos;select SELECTOR=VALUE&apos;, &apos;check SELECTOR&apos;, &apos;set SELECTOR=VALUE&apos;; repeatable</source>
        <translation>was ein Studierender vor dem Hinsehen tut: &apos;click SELECTOR&apos;, &apos;select SELECTOR=VALUE&apos;, &apos;check SELECTOR&apos;, &apos;set SELECTOR=VALUE&apos;; wiederholbar</translation>
    </message>
    <message>
        <source>the frame captured, default 5 (fewer when the page stops drawing)</source>
        <translation>das aufgezeichnete Bild, Vorgabe 5 (früher, wenn die Seite nicht mehr zeichnet)</translation>
    </message>
    <message>
        <source>the time limit of one run of the page, default 20 s</source>
        <translation>das Zeitlimit eines Laufs der Seite, Vorgabe 20 s</translation>
    </message>
    <message>
        <source>check a capture.json of an earlier run again, without the browser</source>
        <translation>eine capture.json eines früheren Laufs erneut prüfen, ohne Browser</translation>
    </message>
    <message>
        <source>the course&apos;s meshes (the Blender cloud and tree) the page&apos;s normals are compared with</source>
        <translation>die Meshes des Kurses (Wolke und Baum aus Blender), mit denen die Normalen der Seite verglichen werden</translation>
    </message>
    <message>
        <source>write capture.json and the browser&apos;s, PhongLab&apos;s and the difference frames here</source>
        <translation>capture.json und die Bilder des Browsers, von PhongLab und der Differenz hierhin schreiben</translation>
    </message>
    <message>
        <source>
Running the page (--page): the project&apos;s page runs in headless Chromium (WebGL on SwiftShader,
a fixed window, a virtual clock, no network), and what it hands WebGL is captured. Then
PhongLab draws the captured frame again and compares it with the browser&apos;s (fidelity),
checks the normals and matrices the JavaScript sent, and with SCENE.json checks the course
scene with the program and the values the page used. JSON adds &quot;page&quot; (keys: file, webgl,
frame, animated, canvas, milliseconds, steps, served, refused, errors, console_errors,
fidelity, javascript, mesh_errors).
</source>
        <translation>
Die Seite ausführen (--page): die Seite des Projekts läuft in headless Chromium (WebGL auf SwiftShader,
festes Fenster, virtuelle Uhr, kein Netzwerk), und was sie WebGL übergibt, wird aufgezeichnet. Dann
zeichnet PhongLab das aufgezeichnete Bild erneut und vergleicht es mit dem des Browsers (Treue),
prüft die Normalen und Matrizen, die das JavaScript gesendet hat, und prüft mit SCENE.json die Kursszene
mit dem Programm und den Werten, die die Seite verwendet hat. JSON enthält zusätzlich &quot;page&quot; (Schlüssel: file, webgl,
frame, animated, canvas, milliseconds, steps, served, refused, errors, console_errors,
fidelity, javascript, mesh_errors).
</translation>
    </message>
    <message>
        <source>--%1: expected %2..%3, got &apos;%4&apos;</source>
        <translation>--%1: %2..%3 erwartet, erhalten &apos;%4&apos;</translation>
    </message>
    <message>
        <source>--page runs the page, --capture checks an earlier run: give one</source>
        <translation>--page führt die Seite aus, --capture prüft einen früheren Lauf: eines angeben</translation>
    </message>
    <message>
        <source>--%1 is about the page of --%2</source>
        <translation>--%1 betrifft die Seite von --%2</translation>
    </message>
    <message>
        <source>--page: %1 is not a folder</source>
        <translation>--page: %1 ist kein Ordner</translation>
    </message>
    <message>
        <source>--page-file is about the page of --page</source>
        <translation>--page-file betrifft die Seite von --page</translation>
    </message>
    <message>
        <source>--library: %1 is not a folder</source>
        <translation>--library: %1 ist kein Ordner</translation>
    </message>
    <message>
        <source>--url-map: expected PREFIX=PATH of an existing file or folder, got &apos;%1&apos;</source>
        <translation>--url-map: PREFIX=PATH einer vorhandenen Datei oder eines Ordners erwartet, erhalten &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--meshes: %1 is not a folder</source>
        <translation>--meshes: %1 ist kein Ordner</translation>
    </message>
    <message>
        <source>--meshes compares a page&apos;s normals: give --%1</source>
        <translation>--meshes vergleicht die Normalen einer Seite: --%1 angeben</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::PageReport</name>
    <message>
        <source>verdict: %1</source>
        <translation>Urteil: %1</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::PngFiles</name>
    <message>
        <source>%1 %2: PhongLab writes PNG images only; give a name that ends in .png</source>
        <translation>%1 %2: PhongLab schreibt nur PNG-Bilder; einen Namen mit der Endung .png angeben</translation>
    </message>
    <message>
        <source>cannot write: %1</source>
        <translation>kann nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <source>PNG encoding failed</source>
        <translation>PNG-Kodierung fehlgeschlagen</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::RenderCommand</name>
    <message>
        <source>Show help.</source>
        <translation>Hilfe anzeigen.</translation>
    </message>
    <message>
        <source>Scene file (JSON).</source>
        <translation>Szenendatei (JSON).</translation>
    </message>
    <message>
        <source>missing the scene file</source>
        <translation>die Szenendatei fehlt</translation>
    </message>
    <message>
        <source>exactly one scene file expected</source>
        <translation>genau eine Szenendatei erwartet</translation>
    </message>
    <message>
        <source>the shaders did not compile; no image written</source>
        <translation>die Shader ließen sich nicht kompilieren; kein Bild geschrieben</translation>
    </message>
    <message>
        <source>rendering failed</source>
        <translation>Rendern fehlgeschlagen</translation>
    </message>
    <message>
        <source>missing -o OUT.png</source>
        <translation>-o OUT.png fehlt</translation>
    </message>
    <message>
        <source>usage: phonglab render SCENE.json -o OUT.png [--size WxH] [--shading NAME] [--vertex FILE] [--fragment FILE] [--bind NAME=MEANING ...]
                       [--define NAME=VALUE ...] [--precision highp|as-written]</source>
        <translation>Aufruf: phonglab render SCENE.json -o OUT.png [--size WxH] [--shading NAME] [--vertex FILE] [--fragment FILE] [--bind NAME=MEANING ...]
                        [--define NAME=VALUE ...] [--precision highp|as-written]</translation>
    </message>
    <message>
        <source>

Renders one frame of SCENE.json offscreen (no multisampling) into an 8-bit RGB PNG.

  -o, --output FILE   the PNG to write (only written when everything succeeded)
%1

Exit status: 0 success, 1 bad input or compile/render failure, 2 wrong arguments.
Compile errors are printed as FILE:LINE:COL: error: MESSAGE.</source>
        <extracomment>%1: the lines of --size, --shading, --vertex, --fragment, --bind, --define and --precision, each option&apos;s own</extracomment>
        <translation>

Rendert ein Bild von SCENE.json offscreen (ohne Multisampling) in ein 8-Bit-RGB-PNG.

  -o, --output FILE   das zu schreibende PNG (wird nur geschrieben, wenn alles gelungen ist)
%1

Exit-Code: 0 Erfolg, 1 ungültige Eingabe oder Kompilier-/Renderfehler, 2 falsche Argumente.
Kompilierfehler werden als FILE:LINE:COL: error: MESSAGE ausgegeben.</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::SceneOverrides</name>
    <message>
        <source>--precision: expected highp or as-written, got &apos;%1&apos;</source>
        <translation>--precision: highp oder as-written erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>what the shader&apos;s uniform or input NAME holds; repeatable. Names are
bound by themselves where they say it (uModelMatrix, aPosition, u_kd);
this wins over that. Meanings: %1, or none; or a constant the
page sets (--bind mode=1, --bind &apos;u_MatlSet[0].emit=0,0,0&apos;)</source>
        <translation>was die Uniform-Variable oder Eingabevariable NAME des Shaders enthält;
wiederholbar. Namen, die es selbst sagen (uModelMatrix, aPosition, u_kd),
werden automatisch zugeordnet; --bind hat Vorrang. Bedeutungen: %1 oder none;
oder eine Konstante, die die Seite setzt (--bind mode=1,
--bind &apos;u_MatlSet[0].emit=0,0,0&apos;)</translation>
    </message>
    <message>
        <source>a token the page&apos;s JavaScript replaces before compiling (NUM_LIGHTS=2);
repeatable</source>
        <translation>ein Platzhalter, den das JavaScript der Seite vor dem Kompilieren ersetzt
(NUM_LIGHTS=2); wiederholbar</translation>
    </message>
    <message>
        <source>highp (default): every float checked at 32 bits, as a desktop browser
computes it, and what mediump or lowp would change said apart;
as-written: the declared precision, as this driver computes it</source>
        <translation>highp (Standard): jede Gleitkommazahl mit 32 Bit beurteilt, so wie ein
Desktop-Browser rechnet, und was mediump oder lowp ändern würden, gesondert
genannt; as-written: die deklarierte Genauigkeit, so wie dieser Treiber rechnet</translation>
    </message>
    <message>
        <source>highp (default: every float at 32 bits, as a desktop browser
computes it) or as-written (the declared precision, as this driver
computes it)</source>
        <translation>highp (Standard: jede Gleitkommazahl mit 32 Bit, so wie ein Desktop-Browser
rechnet) oder as-written (die deklarierte Genauigkeit, so wie dieser Treiber
rechnet)</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::StageOptions</name>
    <message>
        <source>image size in pixels, default 800x600</source>
        <translation>Bildgröße in Pixeln, Standard 800x600</translation>
    </message>
    <message>
        <source>vertex shader instead of the scene&apos;s or the shading method&apos;s</source>
        <translation>Vertex-Shader anstelle dessen der Szene oder des Schattierungsverfahrens</translation>
    </message>
    <message>
        <source>fragment shader instead of the scene&apos;s or the shading method&apos;s</source>
        <translation>Fragment-Shader anstelle dessen der Szene oder des Schattierungsverfahrens</translation>
    </message>
    <message>
        <source>shading method instead of the scene&apos;s &quot;shading&quot;; one of
%1</source>
        <translation>Schattierungsverfahren statt &quot;shading&quot; der Szene; eines von
%1</translation>
    </message>
    <message>
        <source>--size: expected WxH with 1..%1 pixels per side, got &apos;%2&apos;</source>
        <translation>--size: WxH mit 1..%1 Pixeln pro Seite erwartet, erhalten: &apos;%2&apos;</translation>
    </message>
    <message>
        <source>--shading: unknown method &apos;%1&apos; (known: %2)</source>
        <translation>--shading: unbekanntes Verfahren &apos;%1&apos; (bekannt: %2)</translation>
    </message>
    <message>
        <source>; if it is %1, add --bind %2=%3 (or &quot;bindings&quot; in the scene)</source>
        <translation>; falls es sich um %1 handelt, --bind %2=%3 angeben (oder &quot;bindings&quot; in der Szene)</translation>
    </message>
    <message>
        <source>; bind it with --bind %1=MEANING (meanings: %2), or give it a value in the scene&apos;s &quot;uniforms&quot;</source>
        <translation>; mit --bind %1=MEANING binden (Bedeutungen: %2) oder ihr einen Wert in &quot;uniforms&quot; der Szene geben</translation>
    </message>
</context>
<context>
    <name>phonglab::cli::SubmissionArchive</name>
    <message>
        <source>%1: refused: %2</source>
        <translation>%1: abgelehnt: %2</translation>
    </message>
    <message>
        <source>%1: cannot read it as an archive: %2</source>
        <translation>%1: nicht als Archiv lesbar: %2</translation>
    </message>
    <message>
        <source>%1: cannot make the folder %2</source>
        <translation>%1: der Ordner %2 kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>it is damaged (%1)</source>
        <translation>es ist beschädigt (%1)</translation>
    </message>
    <message>
        <source>more than %1 entries</source>
        <translation>mehr als %1 Einträge</translation>
    </message>
    <message>
        <source>the name %1 leaves the folder it is unpacked in</source>
        <translation>der Name %1 verlässt den Ordner, in den entpackt wird</translation>
    </message>
    <message>
        <source>%1 is a link</source>
        <translation>%1 ist ein Link</translation>
    </message>
    <message>
        <source>cannot make %1</source>
        <translation>%1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>%1 is not a plain file</source>
        <translation>%1 ist keine gewöhnliche Datei</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>it is damaged at %1 (%2)</source>
        <translation>es ist bei %1 beschädigt (%2)</translation>
    </message>
    <message>
        <source>more than %1 MiB unpacked</source>
        <translation>mehr als %1 MiB entpackt</translation>
    </message>
    <message>
        <source>a zip bomb: %1 MiB unpacked from %2 KiB and still going</source>
        <translation>eine Zip-Bombe: %1 MiB aus %2 KiB entpackt, und es geht weiter</translation>
    </message>
</context>
</TS>
