<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>FieldOverlay</name>
    <message numerus="yes">
        <source>mean of the last %n step(s)</source>
        <translation>
            <numerusform>Mittel des letzten %n Schritts</numerusform>
            <numerusform>Mittel der letzten %n Schritte</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>mean of %n step(s)</source>
        <translation>
            <numerusform>Mittel über %n Schritt</numerusform>
            <numerusform>Mittel über %n Schritte</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>
Allowed: %1</source>
        <translation>
Erlaubt: %1</translation>
    </message>
    <message>
        <source>
Takes effect at once.</source>
        <translation>
Wirkt sofort.</translation>
    </message>
    <message>
        <source>
Takes effect on Reset.</source>
        <translation>
Wirkt nach „Zurücksetzen“.</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>Cannot encode the PNG image.</source>
        <translation>Das PNG-Bild kann nicht kodiert werden.</translation>
    </message>
    <message>
        <source>Cannot start the SVG renderer.</source>
        <translation>Der SVG-Renderer kann nicht gestartet werden.</translation>
    </message>
    <message>
        <source>Cannot start the PDF renderer.</source>
        <translation>Der PDF-Renderer kann nicht gestartet werden.</translation>
    </message>
    <message>
        <source>The image must be at least 16 × 16 pixels at 24 DPI or more.</source>
        <translation>Das Bild muss mindestens 16 × 16 Pixel bei 24 DPI oder mehr haben.</translation>
    </message>
    <message>
        <source>Unknown image format &apos;.%1&apos;: use .png, .svg or .pdf.</source>
        <translation>Unbekanntes Bildformat „.%1“: .png, .svg oder .pdf verwenden.</translation>
    </message>
    <message>
        <source>Save plot image</source>
        <translation>Diagramm als Bild speichern</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)</source>
        <translation>PNG-Bild (*.png);;SVG-Zeichnung (*.svg);;PDF-Dokument (*.pdf)</translation>
    </message>
    <message>
        <source>Cannot save the image</source>
        <translation>Das Bild kann nicht gespeichert werden</translation>
    </message>
    <message>
        <source>Export plot data</source>
        <translation>Diagrammdaten exportieren</translation>
    </message>
    <message>
        <source>CSV table (*.csv)</source>
        <translation>CSV-Tabelle (*.csv)</translation>
    </message>
    <message>
        <source>Cannot export the data</source>
        <translation>Die Daten können nicht exportiert werden</translation>
    </message>
    <message>
        <source>Save image (PNG, SVG, PDF)…</source>
        <translation>Bild speichern (PNG, SVG, PDF)…</translation>
    </message>
    <message>
        <source>Export data as CSV…</source>
        <translation>Daten als CSV exportieren…</translation>
    </message>
    <message>
        <source>Cannot start the PNG renderer.</source>
        <translation>Die PNG-Ausgabe kann nicht gestartet werden.</translation>
    </message>
</context>
<context>
    <name>SceneDescription</name>
    <message>
        <source>Colour shows the sampled field %1.</source>
        <translation>Farbe: das gemessene Feld %1.</translation>
    </message>
    <message>
        <source>Colours: %1.</source>
        <translation>Farben: %1.</translation>
    </message>
    <message>
        <source>Colour shows %1.</source>
        <translation>Farbe: %1.</translation>
    </message>
    <message>
        <source>Scene: %1</source>
        <translation>Szene: %1</translation>
    </message>
    <message>
        <source>The simulation stopped: its state is no longer physical.</source>
        <translation>Die Simulation ist angehalten: ihr Zustand ist nicht mehr physikalisch.</translation>
    </message>
    <message numerus="yes">
        <source>%n particle(s).</source>
        <translation>
            <numerusform>%n Teilchen.</numerusform>
            <numerusform>%n Teilchen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n obstacle(s).</source>
        <translation>
            <numerusform>%n Hindernis.</numerusform>
            <numerusform>%n Hindernisse.</numerusform>
        </translation>
    </message>
    <message>
        <source>A piston stands at x = %1.</source>
        <translation>Ein Kolben steht bei x = %1.</translation>
    </message>
</context>
<context>
    <name>pl::core</name>
    <message>
        <source>3: molecules scatter isotropically in space; 2: velocities and scattering stay in the plane, like the 2D disk gas (for comparing the two).</source>
        <translation>3: Moleküle streuen isotrop im Raum; 2: Geschwindigkeiten und Streuung bleiben in der Ebene, wie beim 2D-Scheibengas (zum Vergleich der beiden).</translation>
    </message>
    <message>
        <source>A spawned disk overlapping another by more than this fraction of a diameter is refused.</source>
        <translation>Eine erzeugte Scheibe, die eine andere um mehr als diesen Bruchteil eines Durchmessers überlappt, wird abgelehnt.</translation>
    </message>
    <message>
        <source>Added to the constraint&apos;s gradient norm; larger is softer (write-up: 100).</source>
        <translation>Wird zur Gradientennorm der Nebenbedingung addiert; größer ist weicher (Original: 100).</translation>
    </message>
    <message>
        <source>BKW gas</source>
        <translation>BKW-Gas</translation>
    </message>
    <message>
        <source>Beam 1 velocity</source>
        <translation>Geschwindigkeit Strahl 1</translation>
    </message>
    <message>
        <source>Beam 2 velocity</source>
        <translation>Geschwindigkeit Strahl 2</translation>
    </message>
    <message>
        <source>Bins of the speed histogram (write-up: 25).</source>
        <translation>Klassen des Geschwindigkeitshistogramms (Original: 25).</translation>
    </message>
    <message>
        <source>Bins of the speed histogram.</source>
        <translation>Klassen des Geschwindigkeitshistogramms.</translation>
    </message>
    <message>
        <source>Blow-up factor</source>
        <translation>Abbruchfaktor</translation>
    </message>
    <message>
        <source>Bottom edge of the fluid present at t = 0.</source>
        <translation>Unterkante der Flüssigkeit bei t = 0.</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Behälter</translation>
    </message>
    <message>
        <source>Box height</source>
        <translation>Behälterhöhe</translation>
    </message>
    <message>
        <source>Box width</source>
        <translation>Behälterbreite</translation>
    </message>
    <message>
        <source>Cell volume</source>
        <translation>Zellvolumen</translation>
    </message>
    <message>
        <source>Click and drag to pour fluid</source>
        <translation>Klicken und ziehen, um Flüssigkeit einzugießen</translation>
    </message>
    <message>
        <source>Collision time step; keep ν Δt well below 1 (write-up: 2e-5).</source>
        <translation>Zeitschritt der Stöße; ν Δt deutlich unter 1 halten (Original: 2e-5).</translation>
    </message>
    <message>
        <source>Collisions</source>
        <translation>Stöße</translation>
    </message>
    <message>
        <source>Colour (A)</source>
        <translation>Farbe (A)</translation>
    </message>
    <message>
        <source>Colour (B)</source>
        <translation>Farbe (B)</translation>
    </message>
    <message>
        <source>Colour of this species when disks are coloured by species.</source>
        <translation>Farbe dieser Teilchensorte, wenn die Scheiben nach Sorte gefärbt werden.</translation>
    </message>
    <message>
        <source>Colour scale top</source>
        <translation>Obergrenze der Farbskala</translation>
    </message>
    <message>
        <source>Compression the solver left from earlier steps moves the particles but adds at most this much velocity per step, so it is not released as a launch when gravity is switched off. Costs a second solve. 0: off, as in the write-up.</source>
        <translation>Kompression, die der Löser aus früheren Schritten hinterlassen hat, verschiebt die Teilchen, gibt ihnen je Schritt aber höchstens so viel Geschwindigkeit; so schleudert sie das Becken nicht hoch, wenn die Schwerkraft ausgeschaltet wird. Kostet einen zweiten Lösungsdurchgang. 0: aus, wie im Original.</translation>
    </message>
    <message>
        <source>Contact diameter of one A disk. The write-up uses 0.01.</source>
        <translation>Kontaktdurchmesser einer A-Scheibe. Das Original verwendet 0.01.</translation>
    </message>
    <message>
        <source>Contact diameter of one B disk.</source>
        <translation>Kontaktdurchmesser einer B-Scheibe.</translation>
    </message>
    <message>
        <source>Cross-section</source>
        <translation>Stoßquerschnitt</translation>
    </message>
    <message>
        <source>Diameter (A)</source>
        <translation>Durchmesser (A)</translation>
    </message>
    <message>
        <source>Diameter (B)</source>
        <translation>Durchmesser (B)</translation>
    </message>
    <message>
        <source>Disks (A)</source>
        <translation>Scheiben (A)</translation>
    </message>
    <message>
        <source>Disks (B)</source>
        <translation>Scheiben (B)</translation>
    </message>
    <message>
        <source>Display</source>
        <translation>Darstellung</translation>
    </message>
    <message>
        <source>Downward acceleration; 0 for none.</source>
        <translation>Beschleunigung nach unten; 0 für keine.</translation>
    </message>
    <message>
        <source>Drag speed limit</source>
        <translation>Höchstgeschwindigkeit beim Ziehen</translation>
    </message>
    <message>
        <source>Drain over the cap</source>
        <translation>Abfluss über der Obergrenze</translation>
    </message>
    <message>
        <source>Exponent of the artificial pressure (write-up: 4).</source>
        <translation>Exponent des künstlichen Drucks (Original: 4).</translation>
    </message>
    <message>
        <source>Fastest a dragged obstacle moves, in units of the wave speed √(g H) of a tank-deep layer: the fluid always meets a wall of finite speed, whatever the frame rate.</source>
        <translation>Höchstgeschwindigkeit eines gezogenen Hindernisses in Einheiten der Wellengeschwindigkeit √(g H) einer beckentiefen Schicht: Die Flüssigkeit trifft stets auf eine Wand endlicher Geschwindigkeit, unabhängig von der Bildrate.</translation>
    </message>
    <message>
        <source>Fastest a dragged obstacle or the piston moves, in units of the initial rms speed: the disks always meet a wall of finite speed, whatever the frame rate.</source>
        <translation>Höchstgeschwindigkeit eines gezogenen Hindernisses oder des Kolbens in Einheiten der anfänglichen quadratisch gemittelten Geschwindigkeit: Die Scheiben treffen stets auf eine Wand endlicher Geschwindigkeit, unabhängig von der Bildrate.</translation>
    </message>
    <message>
        <source>First guess of (σ c_r)_max (write-up: 1e-18); 0 estimates it from the initial state. It is raised whenever a pair exceeds it.</source>
        <translation>Erste Schätzung von (σ c_r)_max (Original: 1e-18); 0 schätzt ihn aus dem Anfangszustand. Er wird erhöht, sobald ein Paar ihn übertrifft.</translation>
    </message>
    <message>
        <source>Fluid (position-based)</source>
        <translation>Flüssigkeit (positionsbasiert)</translation>
    </message>
    <message>
        <source>Force search</source>
        <translation>Kraftsuche</translation>
    </message>
    <message>
        <source>Gas (molecular dynamics)</source>
        <translation>Gas (Molekulardynamik)</translation>
    </message>
    <message>
        <source>Gas and cell</source>
        <translation>Gas und Zelle</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <source>Gravity on</source>
        <translation>Schwerkraft an</translation>
    </message>
    <message>
        <source>Gravity x</source>
        <translation>Schwerkraft x</translation>
    </message>
    <message>
        <source>Grid spacing of spawned fluid in units of h (write-up: 0.8).</source>
        <translation>Gitterabstand erzeugter Flüssigkeit in Einheiten von h (Original: 0.8).</translation>
    </message>
    <message>
        <source>Hard-sphere diameter</source>
        <translation>Harte-Kugel-Durchmesser</translation>
    </message>
    <message>
        <source>Height of the container; the write-up&apos;s box is 2 high.</source>
        <translation>Höhe des Behälters; der Behälter des Originals ist 2 hoch.</translation>
    </message>
    <message>
        <source>Height of the tank (write-up: 40).</source>
        <translation>Höhe des Beckens (Original: 40).</translation>
    </message>
    <message>
        <source>Histogram bins</source>
        <translation>Histogrammklassen</translation>
    </message>
    <message>
        <source>Histogram range</source>
        <translation>Histogrammbereich</translation>
    </message>
    <message>
        <source>Horizontal component of gravity.</source>
        <translation>Waagerechte Komponente der Schwerkraft.</translation>
    </message>
    <message>
        <source>Include W(0) in each particle&apos;s density, as SPH does (the write-up omits it).</source>
        <translation>W(0) in die Dichte jedes Teilchens einbeziehen, wie bei SPH (das Original lässt ihn weg).</translation>
    </message>
    <message>
        <source>Initial (σ c_r)_max</source>
        <translation>Anfängliches (σ c_r)_max</translation>
    </message>
    <message>
        <source>Initial block x₀</source>
        <translation>Anfangsblock x₀</translation>
    </message>
    <message>
        <source>Initial block x₁</source>
        <translation>Anfangsblock x₁</translation>
    </message>
    <message>
        <source>Initial block y₀</source>
        <translation>Anfangsblock y₀</translation>
    </message>
    <message>
        <source>Initial block y₁</source>
        <translation>Anfangsblock y₁</translation>
    </message>
    <message>
        <source>Initial kT</source>
        <translation>Anfangs-kT</translation>
    </message>
    <message>
        <source>Initial placement</source>
        <translation>Anfangsanordnung</translation>
    </message>
    <message>
        <source>Initial speed</source>
        <translation>Anfangsgeschwindigkeit</translation>
    </message>
    <message>
        <source>Initial state</source>
        <translation>Anfangszustand</translation>
    </message>
    <message>
        <source>Initial velocities</source>
        <translation>Anfangsgeschwindigkeiten</translation>
    </message>
    <message>
        <source>Integration</source>
        <translation>Integration</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>Interaction</source>
        <translation>Wechselwirkung</translation>
    </message>
    <message>
        <source>Iterations</source>
        <translation>Iterationen</translation>
    </message>
    <message>
        <source>Jacobi iterations of the density constraint per step (write-up: 5).</source>
        <translation>Jacobi-Iterationen der Dichtebedingung pro Schritt (Original: 5).</translation>
    </message>
    <message>
        <source>Kernel constants</source>
        <translation>Kernkonstanten</translation>
    </message>
    <message>
        <source>Kernel radius h</source>
        <translation>Kernradius h</translation>
    </message>
    <message>
        <source>Left edge of the fluid present at t = 0.</source>
        <translation>Linke Kante der Flüssigkeit bei t = 0.</translation>
    </message>
    <message>
        <source>Limits</source>
        <translation>Grenzen</translation>
    </message>
    <message>
        <source>Mass (A)</source>
        <translation>Masse (A)</translation>
    </message>
    <message>
        <source>Mass (B)</source>
        <translation>Masse (B)</translation>
    </message>
    <message>
        <source>Mass of one A disk.</source>
        <translation>Masse einer A-Scheibe.</translation>
    </message>
    <message>
        <source>Mass of one B disk.</source>
        <translation>Masse einer B-Scheibe.</translation>
    </message>
    <message>
        <source>Mass of one molecule; O2 is 32.</source>
        <translation>Masse eines Moleküls; O2 hat 32.</translation>
    </message>
    <message>
        <source>Maxwell σ c_r</source>
        <translation>Maxwell-σ c_r</translation>
    </message>
    <message>
        <source>Molecular diameter of the hard-sphere model.</source>
        <translation>Moleküldurchmesser im Modell harter Kugeln.</translation>
    </message>
    <message>
        <source>Molecular mass</source>
        <translation>Molekülmasse</translation>
    </message>
    <message>
        <source>Most disks the scene may hold; spawning stops here.</source>
        <translation>Höchstzahl der Scheiben in der Szene; darüber wird nichts mehr erzeugt.</translation>
    </message>
    <message>
        <source>Most particles in the tank (write-up: 3000).</source>
        <translation>Höchstzahl der Teilchen im Becken (Original: 3000).</translation>
    </message>
    <message>
        <source>Neighbour radius / h</source>
        <translation>Nachbarradius / h</translation>
    </message>
    <message>
        <source>Neighbours are searched within this multiple of h (write-up: 1.05).</source>
        <translation>Nachbarn werden innerhalb dieses Vielfachen von h gesucht (Original: 1.05).</translation>
    </message>
    <message>
        <source>Number of disks of species A; the write-up has 4096.</source>
        <translation>Anzahl der Scheiben der Sorte A; das Original hat 4096.</translation>
    </message>
    <message>
        <source>Number of disks of species B; 0 for a one-species gas.</source>
        <translation>Anzahl der Scheiben der Sorte B; 0 für ein Gas aus einer Sorte.</translation>
    </message>
    <message>
        <source>Observation</source>
        <translation>Beobachtung</translation>
    </message>
    <message>
        <source>On: the lowest particles drain away over the cap (the write-up); off: spawns over the cap are refused.</source>
        <translation>An: Über der Obergrenze fließen die untersten Teilchen ab (wie im Original); aus: Erzeugen über der Obergrenze wird abgelehnt.</translation>
    </message>
    <message>
        <source>Particle cap</source>
        <translation>Teilchenobergrenze</translation>
    </message>
    <message>
        <source>Particle radius</source>
        <translation>Teilchenradius</translation>
    </message>
    <message>
        <source>Particle weight F_N</source>
        <translation>Teilchengewicht F_N</translation>
    </message>
    <message>
        <source>Particles</source>
        <translation>Teilchen</translation>
    </message>
    <message>
        <source>Particles (beam 1)</source>
        <translation>Teilchen (Strahl 1)</translation>
    </message>
    <message>
        <source>Particles (beam 2)</source>
        <translation>Teilchen (Strahl 2)</translation>
    </message>
    <message>
        <source>Piston</source>
        <translation>Kolben</translation>
    </message>
    <message>
        <source>Piston position</source>
        <translation>Kolbenposition</translation>
    </message>
    <message>
        <source>Piston speed</source>
        <translation>Kolbengeschwindigkeit</translation>
    </message>
    <message>
        <source>Pressure pushes only</source>
        <translation>Druck drückt nur</translation>
    </message>
    <message>
        <source>Pressure window</source>
        <translation>Mittelungszeit des Drucks</translation>
    </message>
    <message>
        <source>Rarefied gas (DSMC)</source>
        <translation>Verdünntes Gas (DSMC)</translation>
    </message>
    <message>
        <source>Re-injects vorticity lost to damping; 0: off, as in the write-up.</source>
        <translation>Führt durch Dämpfung verlorene Wirbelstärke wieder zu; 0: aus, wie im Original.</translation>
    </message>
    <message>
        <source>Real molecules each simulated particle stands for (write-up: 5e8).</source>
        <translation>Reale Moleküle, für die jedes simulierte Teilchen steht (Original: 5e8).</translation>
    </message>
    <message>
        <source>Reference distance of the artificial pressure (write-up: 0.3).</source>
        <translation>Bezugsabstand des künstlichen Drucks (Original: 0.3).</translation>
    </message>
    <message>
        <source>Release of old compression</source>
        <translation>Freigabe alter Kompression</translation>
    </message>
    <message>
        <source>Relaxation ε</source>
        <translation>Relaxation ε</translation>
    </message>
    <message>
        <source>Replace the right wall by a movable piston.</source>
        <translation>Die rechte Wand durch einen beweglichen Kolben ersetzen.</translation>
    </message>
    <message>
        <source>Rest density from</source>
        <translation>Ruhedichte aus</translation>
    </message>
    <message>
        <source>Rest density ρ₀</source>
        <translation>Ruhedichte ρ₀</translation>
    </message>
    <message>
        <source>Right edge of the initial block; x₁ ≤ x₀ starts empty (the write-up).</source>
        <translation>Rechte Kante des Anfangsblocks; x₁ ≤ x₀ beginnt leer (wie im Original).</translation>
    </message>
    <message>
        <source>Run length</source>
        <translation>Laufdauer</translation>
    </message>
    <message>
        <source>Self term in ρ</source>
        <translation>Eigenterm in ρ</translation>
    </message>
    <message>
        <source>Signed step; negative runs time backwards. The write-up uses 1e-4.</source>
        <translation>Vorzeichenbehafteter Schritt; negativ lässt die Zeit rückwärts laufen. Das Original verwendet 1e-4.</translation>
    </message>
    <message>
        <source>Simulated particles of beam 1, or of the single gas.</source>
        <translation>Simulierte Teilchen von Strahl 1 oder des einzelnen Gases.</translation>
    </message>
    <message>
        <source>Simulated particles of beam 2 (two-beams only).</source>
        <translation>Simulierte Teilchen von Strahl 2 (nur bei two-beams).</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Löser</translation>
    </message>
    <message>
        <source>Spawn overlap limit</source>
        <translation>Überlappungsgrenze beim Erzeugen</translation>
    </message>
    <message>
        <source>Spawn spacing / h</source>
        <translation>Erzeugungsabstand / h</translation>
    </message>
    <message>
        <source>Species A</source>
        <translation>Sorte A</translation>
    </message>
    <message>
        <source>Species B</source>
        <translation>Sorte B</translation>
    </message>
    <message>
        <source>Speed drawn fully red (write-up: 5).</source>
        <translation>Geschwindigkeit, die voll rot gezeichnet wird (Original: 5).</translation>
    </message>
    <message>
        <source>Speed of Compress and Expand, in units of the initial rms speed: well below 1 the gas follows the adiabat T·A = const; near 1 it heats more.</source>
        <translation>Geschwindigkeit von Verdichten und Entspannen in Einheiten der anfänglichen quadratisch gemittelten Geschwindigkeit: deutlich unter 1 folgt das Gas der Adiabate T·A = const; nahe 1 erwärmt es sich stärker.</translation>
    </message>
    <message>
        <source>Speed of every disk for fixed-speed starts; the write-up uses 1.</source>
        <translation>Geschwindigkeit jeder Scheibe beim Start fixed-speed; das Original verwendet 1.</translation>
    </message>
    <message>
        <source>Spring constant of the harmonic repulsion U = k/2 (d − r)²; the write-up uses 1000.</source>
        <translation>Federkonstante der harmonischen Abstoßung U = k/2 (d − r)²; das Original verwendet 1000.</translation>
    </message>
    <message>
        <source>Step Δt (write-up: 1/20 = 0.05).</source>
        <translation>Schritt Δt (Original: 1/20 = 0.05).</translation>
    </message>
    <message>
        <source>Stiffness k</source>
        <translation>Steifigkeit k</translation>
    </message>
    <message>
        <source>Strength of the artificial pressure (write-up: 0.001); 0: off.</source>
        <translation>Stärke des künstlichen Drucks (Original: 0.001); 0: aus.</translation>
    </message>
    <message>
        <source>Support radius of the kernels (write-up: 1.1); spawn spacing is 0.8 h.</source>
        <translation>Trägerradius der Kerne (Original: 1.1); der Erzeugungsabstand ist 0.8 h.</translation>
    </message>
    <message>
        <source>Target density with unit masses (write-up: 1).</source>
        <translation>Zieldichte bei Einheitsmassen (Original: 1).</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <source>Temperature at which d = d_ref (273 K).</source>
        <translation>Temperatur, bei der d = d_ref gilt (273 K).</translation>
    </message>
    <message>
        <source>Temperature of each beam, or of the single gas (write-up: 5).</source>
        <translation>Temperatur jedes Strahls oder des einzelnen Gases (Original: 5).</translation>
    </message>
    <message>
        <source>Temperature of maxwell-boltzmann starts and of spawned disks.</source>
        <translation>Temperatur beim Start maxwell-boltzmann und der erzeugten Scheiben.</translation>
    </message>
    <message>
        <source>Temperature of thermal walls.</source>
        <translation>Temperatur thermischer Wände.</translation>
    </message>
    <message>
        <source>The constant σ c_r of Maxwell molecules.</source>
        <translation>Das konstante σ c_r von Maxwell-Molekülen.</translation>
    </message>
    <message>
        <source>The run stops after this many steps (write-up: 500); 0 runs on.</source>
        <translation>Der Lauf endet nach so vielen Schritten (Original: 500); 0 läuft unbegrenzt.</translation>
    </message>
    <message>
        <source>The run stops after this many steps; 0 runs on (the write-up).</source>
        <translation>Der Lauf endet nach so vielen Schritten; 0 läuft unbegrenzt (wie im Original).</translation>
    </message>
    <message>
        <source>The run stops when the total energy exceeds this multiple of its reference.</source>
        <translation>Der Lauf endet, wenn die Gesamtenergie dieses Vielfache ihres Bezugswerts übersteigt.</translation>
    </message>
    <message>
        <source>The density constraint as ρ ≤ ρ₀: compressed fluid pushes apart, under-dense fluid (the free surface, along the walls) does not pull together. Off: the paper&apos;s equality, as in the write-up.</source>
        <translation>Die Dichtebedingung als ρ ≤ ρ₀: Komprimierte Flüssigkeit drückt auseinander, zu dünne (die freie Oberfläche, entlang der Wände) zieht sich nicht zusammen. Aus: die Gleichung des Artikels, wie im Original.</translation>
    </message>
    <message>
        <source>The write-up&apos;s gravity toggle (key G).</source>
        <translation>Der Schwerkraftschalter des Originals (Taste G).</translation>
    </message>
    <message>
        <source>Time over which wall impulses are averaged into a pressure.</source>
        <translation>Zeit, über die Wandimpulse zu einem Druck gemittelt werden.</translation>
    </message>
    <message>
        <source>Time step</source>
        <translation>Zeitschritt</translation>
    </message>
    <message>
        <source>Time-stepping method; velocity Verlet is symplectic and time-reversible.</source>
        <translation>Zeitschrittverfahren; Velocity-Verlet ist symplektisch und zeitumkehrbar.</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <source>Top edge of the initial block.</source>
        <translation>Oberkante des Anfangsblocks.</translation>
    </message>
    <message>
        <source>Upper end of the speed histogram (write-up: 450).</source>
        <translation>Oberes Ende des Geschwindigkeitshistogramms (Original: 450).</translation>
    </message>
    <message>
        <source>VHS T_ref</source>
        <translation>VHS T_ref</translation>
    </message>
    <message>
        <source>VHS d_ref</source>
        <translation>VHS d_ref</translation>
    </message>
    <message>
        <source>VHS reference diameter (O2: 4.07e-10).</source>
        <translation>VHS-Bezugsdurchmesser (O2: 4.07e-10).</translation>
    </message>
    <message>
        <source>VHS ω</source>
        <translation>VHS ω</translation>
    </message>
    <message>
        <source>Velocity components</source>
        <translation>Geschwindigkeitskomponenten</translation>
    </message>
    <message>
        <source>Velocity of beam 1 along x (write-up: 100).</source>
        <translation>Geschwindigkeit von Strahl 1 in x-Richtung (Original: 100).</translation>
    </message>
    <message>
        <source>Velocity of beam 2 along x (write-up: 300).</source>
        <translation>Geschwindigkeit von Strahl 2 in x-Richtung (Original: 300).</translation>
    </message>
    <message>
        <source>Velocity smoothing of the paper (0.01 there); 0: off, as in the write-up.</source>
        <translation>Geschwindigkeitsglättung aus dem Artikel (dort 0.01); 0: aus, wie im Original.</translation>
    </message>
    <message>
        <source>Viscosity index: 0.5 hard sphere, 1 Maxwell, O2 0.77.</source>
        <translation>Viskositätsexponent: 0.5 harte Kugel, 1 Maxwell, O2 0.77.</translation>
    </message>
    <message>
        <source>Volume of the collision cell (write-up: 1e-8).</source>
        <translation>Volumen der Stoßzelle (Original: 1e-8).</translation>
    </message>
    <message>
        <source>Vorticity confinement ε</source>
        <translation>Wirbelverstärkung ε</translation>
    </message>
    <message>
        <source>Wall kT</source>
        <translation>Wand-kT</translation>
    </message>
    <message>
        <source>Walls</source>
        <translation>Wände</translation>
    </message>
    <message>
        <source>Walls and fields</source>
        <translation>Wände und Felder</translation>
    </message>
    <message>
        <source>Walls and obstacles keep particle centres this far away (0.3).</source>
        <translation>Wände und Hindernisse halten Teilchenmittelpunkte so weit entfernt (0.3).</translation>
    </message>
    <message>
        <source>Width of the container; the write-up&apos;s box is 2 wide.</source>
        <translation>Breite des Behälters; der Behälter des Originals ist 2 breit.</translation>
    </message>
    <message>
        <source>Width of the tank (write-up: 80).</source>
        <translation>Breite des Beckens (Original: 80).</translation>
    </message>
    <message>
        <source>World</source>
        <translation>Welt</translation>
    </message>
    <message>
        <source>XSPH viscosity c</source>
        <translation>XSPH-Viskosität c</translation>
    </message>
    <message>
        <source>all particles</source>
        <translation>alle Teilchen</translation>
    </message>
    <message>
        <source>cell-list: O(N) neighbour search; all-pairs: the write-up&apos;s O(N²) loop, for comparison.</source>
        <translation>cell-list: Nachbarsuche in O(N); all-pairs: die O(N²)-Schleife des Originals, zum Vergleich.</translation>
    </message>
    <message>
        <source>fixed-speed: every disk at init_speed in a random direction (the write-up); maxwell-boltzmann: Gaussian components at init_kT.</source>
        <translation>fixed-speed: jede Scheibe mit init_speed in zufälliger Richtung (wie im Original); maxwell-boltzmann: gaußverteilte Komponenten bei init_kT.</translation>
    </message>
    <message>
        <source>population</source>
        <translation>Population</translation>
    </message>
    <message>
        <source>random: uniform positions, overlaps allowed (the write-up); lattice: a square lattice, no overlaps.</source>
        <translation>random: gleichverteilte Orte, Überlappungen erlaubt (wie im Original); lattice: ein Quadratgitter ohne Überlappungen.</translation>
    </message>
    <message>
        <source>reflecting: elastic walls; thermal: disks leave a wall with velocities drawn at wall_kT (heating or cooling).</source>
        <translation>reflecting: elastische Wände; thermal: Scheiben verlassen eine Wand mit bei wall_kT gezogenen Geschwindigkeiten (heizt oder kühlt).</translation>
    </message>
    <message>
        <source>s_corr k</source>
        <translation>s_corr k</translation>
    </message>
    <message>
        <source>s_corr n</source>
        <translation>s_corr n</translation>
    </message>
    <message>
        <source>s_corr Δq / h</source>
        <translation>s_corr Δq / h</translation>
    </message>
    <message>
        <source>3d: poly6 315/(64π h⁹), spiky 45/(π h⁶), as written (3D constants in 2D); 2d: 4/(π h⁸) and 30/(π h⁵).</source>
        <translation>3d: poly6 315/(64π h⁹), spiky 45/(π h⁶), wie im Original (3D-Konstanten in 2D); 2d: 4/(π h⁸) und 30/(π h⁵).</translation>
    </message>
    <message>
        <source>inverse-root: σ = 1e-18 c_r^-1/2 m² as written; hard-sphere: σ = π d²; vhs: variable hard sphere (d_ref, T_ref, ω); maxwell: σ c_r constant.</source>
        <translation>inverse-root: σ = 1e-18 c_r^-1/2 m² wie im Original; hard-sphere: σ = π d²; vhs: variable harte Kugel (d_ref, T_ref, ω); maxwell: σ c_r konstant.</translation>
    </message>
    <message>
        <source>species A</source>
        <translation>Sorte A</translation>
    </message>
    <message>
        <source>species B</source>
        <translation>Sorte B</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>speed [L/T]</source>
        <translation>Geschwindigkeit [L/T]</translation>
    </message>
    <message>
        <source>speed [m/s]</source>
        <translation>Geschwindigkeit [m/s]</translation>
    </message>
    <message>
        <source>two-beams: the write-up&apos;s beams along x; maxwellian: one gas at rest; bkw: the BKW initial distribution (K₀ = 0.6).</source>
        <translation>two-beams: die Strahlen des Originals in x-Richtung; maxwellian: ein ruhendes Gas; bkw: die BKW-Anfangsverteilung (K₀ = 0.6).</translation>
    </message>
    <message>
        <source>v_x [m/s]</source>
        <translation>v_x [m/s]</translation>
    </message>
    <message>
        <source>v_y [m/s]</source>
        <translation>v_y [m/s]</translation>
    </message>
    <message>
        <source>value: ρ₀ = rest_density; spawn-lattice: ρ₀ is the density of a particle inside the spawn grid, so spawned fluid starts at rest.</source>
        <translation>value: ρ₀ = rest_density; spawn-lattice: ρ₀ ist die Dichte eines Teilchens im Erzeugungsgitter, sodass erzeugte Flüssigkeit in Ruhe beginnt.</translation>
    </message>
    <message>
        <source>x of the piston; moving it compresses or expands the gas.</source>
        <translation>x-Position des Kolbens; ihn zu bewegen verdichtet oder entspannt das Gas.</translation>
    </message>
    <message>
        <source>K</source>
        <translation>K</translation>
    </message>
    <message>
        <source>L</source>
        <translation>L</translation>
    </message>
    <message>
        <source>L/T</source>
        <translation>L/T</translation>
    </message>
    <message>
        <source>L/T²</source>
        <translation>L/T²</translation>
    </message>
    <message>
        <source>L/s</source>
        <translation>L/s</translation>
    </message>
    <message>
        <source>L/s²</source>
        <translation>L/s²</translation>
    </message>
    <message>
        <source>M</source>
        <translation>M</translation>
    </message>
    <message>
        <source>M/T²</source>
        <translation>M/T²</translation>
    </message>
    <message>
        <source>M·L²/T²</source>
        <translation>M·L²/T²</translation>
    </message>
    <message>
        <source>T</source>
        <translation>T</translation>
    </message>
    <message>
        <source>d</source>
        <translation>d</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>m³</source>
        <translation>m³</translation>
    </message>
    <message>
        <source>m³/s</source>
        <translation>m³/s</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>u</source>
        <translation>u</translation>
    </message>
    <message>
        <source>× rms speed</source>
        <translation>× rms-Geschwindigkeit</translation>
    </message>
    <message>
        <source>× |g| Δt</source>
        <translation>× |g| Δt</translation>
    </message>
    <message>
        <source>× √(g H)</source>
        <translation>× √(g H)</translation>
    </message>
    <message>
        <source>exploded</source>
        <translation>explodiert</translation>
    </message>
    <message>
        <source>inaccurate</source>
        <translation>ungenau</translation>
    </message>
    <message>
        <source>over-compressed</source>
        <translation>überkomprimiert</translation>
    </message>
    <message>
        <source>rejected</source>
        <translation>abgelehnt</translation>
    </message>
    <message>
        <source>stable</source>
        <translation>stabil</translation>
    </message>
    <message>
        <source>unstable</source>
        <translation>instabil</translation>
    </message>
    <message>
        <source>(σ c_r)_max</source>
        <translation>(σ c_r)_max</translation>
    </message>
    <message>
        <source>(σ c_r)_max [m³/s]</source>
        <translation>(σ c_r)_max [m³/s]</translation>
    </message>
    <message>
        <source>Dam-break front</source>
        <translation>Dammbruchfront</translation>
    </message>
    <message>
        <source>Density error</source>
        <translation>Dichtefehler</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Energie</translation>
    </message>
    <message>
        <source>Flow</source>
        <translation>Strömung</translation>
    </message>
    <message>
        <source>KL divergence [nats]</source>
        <translation>KL-Divergenz [nats]</translation>
    </message>
    <message>
        <source>KL to Maxwellian</source>
        <translation>KL zur Maxwell-Verteilung</translation>
    </message>
    <message>
        <source>M4</source>
        <translation>M4</translation>
    </message>
    <message>
        <source>M4 exact (BKW)</source>
        <translation>M4 exakt (BKW)</translation>
    </message>
    <message>
        <source>M6</source>
        <translation>M6</translation>
    </message>
    <message>
        <source>M6 exact (BKW)</source>
        <translation>M6 exakt (BKW)</translation>
    </message>
    <message>
        <source>M8</source>
        <translation>M8</translation>
    </message>
    <message>
        <source>M8 exact (BKW)</source>
        <translation>M8 exakt (BKW)</translation>
    </message>
    <message>
        <source>M_2k / M_2k(eq)</source>
        <translation>M_2k / M_2k(eq)</translation>
    </message>
    <message>
        <source>Moments</source>
        <translation>Momente</translation>
    </message>
    <message>
        <source>N kT / A</source>
        <translation>N kT / A</translation>
    </message>
    <message>
        <source>P from the virial</source>
        <translation>P aus dem Virial</translation>
    </message>
    <message>
        <source>P from wall impulses</source>
        <translation>P aus Wandimpulsen</translation>
    </message>
    <message>
        <source>T = n t √(g/a)</source>
        <translation>T = n t √(g/a)</translation>
    </message>
    <message>
        <source>T_x</source>
        <translation>T_x</translation>
    </message>
    <message>
        <source>|T_x − T_⊥| [K]</source>
        <translation>|T_x − T_⊥| [K]</translation>
    </message>
    <message>
        <source>T_⊥</source>
        <translation>T_⊥</translation>
    </message>
    <message>
        <source>Temperatures</source>
        <translation>Temperaturen</translation>
    </message>
    <message>
        <source>The gravity switch (key G); off, the disks feel none.</source>
        <translation>Der Schalter der Schwerkraft (Taste G); aus, spüren die Scheiben keine.</translation>
    </message>
    <message>
        <source>Thermodynamics</source>
        <translation>Thermodynamik</translation>
    </message>
    <message>
        <source>anisotropy</source>
        <translation>Anisotropie</translation>
    </message>
    <message>
        <source>candidates ng</source>
        <translation>Kandidaten ng</translation>
    </message>
    <message>
        <source>collisions nc</source>
        <translation>Stöße nc</translation>
    </message>
    <message>
        <source>compression ρ/ρ₀ − 1</source>
        <translation>Kompression ρ/ρ₀ − 1</translation>
    </message>
    <message>
        <source>energy</source>
        <translation>Energie</translation>
    </message>
    <message>
        <source>front Z = z / a</source>
        <translation>Front Z = z / a</translation>
    </message>
    <message>
        <source>iterations done in the last step</source>
        <translation>Iterationen im letzten Schritt</translation>
    </message>
    <message>
        <source>kT</source>
        <translation>kT</translation>
    </message>
    <message>
        <source>kT of A</source>
        <translation>kT von A</translation>
    </message>
    <message>
        <source>kT of B</source>
        <translation>kT von B</translation>
    </message>
    <message>
        <source>kinetic</source>
        <translation>kinetisch</translation>
    </message>
    <message>
        <source>kinetic energy Σ ½ v²</source>
        <translation>kinetische Energie Σ ½ v²</translation>
    </message>
    <message>
        <source>max</source>
        <translation>Max.</translation>
    </message>
    <message>
        <source>mean</source>
        <translation>Mittel</translation>
    </message>
    <message>
        <source>min</source>
        <translation>Min.</translation>
    </message>
    <message>
        <source>neighbours within h</source>
        <translation>Nachbarn innerhalb h</translation>
    </message>
    <message>
        <source>pairs per step</source>
        <translation>Paare pro Schritt</translation>
    </message>
    <message>
        <source>potential</source>
        <translation>potentiell</translation>
    </message>
    <message>
        <source>pressure</source>
        <translation>Druck</translation>
    </message>
    <message>
        <source>relative drift</source>
        <translation>relative Drift</translation>
    </message>
    <message>
        <source>shallow-water bound 1 + 2T</source>
        <translation>Flachwasserschranke 1 + 2T</translation>
    </message>
    <message>
        <source>surge front</source>
        <translation>Flutfront</translation>
    </message>
    <message>
        <source>temperature [K]</source>
        <translation>Temperatur [K]</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>|E − E₀| / E₀</source>
        <translation>|E − E₀| / E₀</translation>
    </message>
    <message>
        <source>classical Runge–Kutta on (x, v); slowly loses energy</source>
        <translation>klassisches Runge–Kutta-Verfahren für (x, v); verliert langsam Energie</translation>
    </message>
    <message>
        <source>drift h with v_n, kick h with a(x_n), forces; gains energy every step</source>
        <translation>Drift h mit v_n, Kick h mit a(x_n), Kräfte; gewinnt mit jedem Schritt Energie</translation>
    </message>
    <message>
        <source>kick h, drift h, forces; symplectic</source>
        <translation>Kick h, Drift h, Kräfte; symplektisch</translation>
    </message>
    <message>
        <source>kick h/2, drift h, forces, kick h/2; symplectic, time-reversible</source>
        <translation>Kick h/2, Drift h, Kräfte, Kick h/2; symplektisch, zeitumkehrbar</translation>
    </message>
    <message>
        <source>three Verlet steps of θh, (1−2θ)h, θh; symplectic, time-reversible</source>
        <translation>drei Verlet-Schritte von θh, (1−2θ)h, θh; symplektisch, zeitumkehrbar</translation>
    </message>
    <message>
        <source>Bodies and piston</source>
        <translation>Körper und Kolben</translation>
    </message>
    <message>
        <source>Body surface</source>
        <translation>Körperoberfläche</translation>
    </message>
    <message>
        <source>Body temperature</source>
        <translation>Körpertemperatur</translation>
    </message>
    <message>
        <source>Bottom side</source>
        <translation>Untere Seite</translation>
    </message>
    <message>
        <source>Bottom wall speed</source>
        <translation>Geschwindigkeit der unteren Wand</translation>
    </message>
    <message>
        <source>Cells along x</source>
        <translation>Zellen entlang x</translation>
    </message>
    <message>
        <source>Cells along y</source>
        <translation>Zellen entlang y</translation>
    </message>
    <message>
        <source>Collision and sampling cells along x; Bird&apos;s guideline is a cell width below λ/2.</source>
        <translation>Stoß- und Mittelungszellen entlang x; nach Bird ist eine Zellbreite unter λ/2 angemessen.</translation>
    </message>
    <message>
        <source>Collision and sampling cells along y.</source>
        <translation>Stoß- und Mittelungszellen entlang y.</translation>
    </message>
    <message>
        <source>Domain and method</source>
        <translation>Gebiet und Verfahren</translation>
    </message>
    <message>
        <source>Fastest a dragged body or the piston moves.</source>
        <translation>Höchste Geschwindigkeit, mit der sich ein gezogener Körper oder der Kolben bewegt.</translation>
    </message>
    <message>
        <source>Flow speed</source>
        <translation>Strömungsgeschwindigkeit</translation>
    </message>
    <message>
        <source>Flow speed [m/s]</source>
        <translation>Strömungsgeschwindigkeit [m/s]</translation>
    </message>
    <message>
        <source>Forces on the bodies</source>
        <translation>Kräfte auf die Körper</translation>
    </message>
    <message>
        <source>Free stream</source>
        <translation>Freie Anströmung</translation>
    </message>
    <message>
        <source>Gas</source>
        <translation>Gas</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <source>Height of the domain (y); the depth is 1 m.</source>
        <translation>Höhe des Gebiets (y); die Tiefe ist 1 m.</translation>
    </message>
    <message>
        <source>Initial gas</source>
        <translation>Anfangsgas</translation>
    </message>
    <message>
        <source>Keep it below a quarter of the mean collision time and the stream&apos;s cell transit time.</source>
        <translation>Unter einem Viertel der mittleren Stoßzeit und der Zeit, in der die Strömung eine Zelle durchquert, halten.</translation>
    </message>
    <message>
        <source>Left side</source>
        <translation>Linke Seite</translation>
    </message>
    <message>
        <source>Length of the domain along the stream (x).</source>
        <translation>Länge des Gebiets in Strömungsrichtung (x).</translation>
    </message>
    <message>
        <source>Mach number</source>
        <translation>Machzahl</translation>
    </message>
    <message>
        <source>Mass of one molecule; argon is 39.948.</source>
        <translation>Masse eines Moleküls; Argon hat 39,948.</translation>
    </message>
    <message>
        <source>Molecules</source>
        <translation>Moleküle</translation>
    </message>
    <message>
        <source>Number density</source>
        <translation>Teilchendichte</translation>
    </message>
    <message>
        <source>Number density [m⁻³]</source>
        <translation>Teilchendichte [m⁻³]</translation>
    </message>
    <message>
        <source>Number density of the free stream.</source>
        <translation>Teilchendichte der freien Anströmung.</translation>
    </message>
    <message>
        <source>Rarefied flow (DSMC)</source>
        <translation>Verdünnte Strömung (DSMC)</translation>
    </message>
    <message>
        <source>Real molecules (per m of depth) each simulated particle stands for; aim for ≥ 5 particles per free-stream cell.</source>
        <translation>Reale Moleküle (je m Tiefe), für die ein simuliertes Teilchen steht; anzustreben sind ≥ 5 Teilchen je Zelle der freien Anströmung.</translation>
    </message>
    <message>
        <source>Right side</source>
        <translation>Rechte Seite</translation>
    </message>
    <message>
        <source>Sampling and view</source>
        <translation>Mittelung und Ansicht</translation>
    </message>
    <message>
        <source>Sampling starts after</source>
        <translation>Mittelung beginnt nach</translation>
    </message>
    <message>
        <source>Sides</source>
        <translation>Seiten</translation>
    </message>
    <message>
        <source>Speed along +x of a diffuse bottom side (Couette flow).</source>
        <translation>Geschwindigkeit einer diffusen unteren Seite entlang +x (Couette-Strömung).</translation>
    </message>
    <message>
        <source>Speed along +x of a diffuse top side.</source>
        <translation>Geschwindigkeit einer diffusen oberen Seite entlang +x.</translation>
    </message>
    <message>
        <source>Speed of the driven piston; &gt; 0 at the start drives it into the gas from t = 0.</source>
        <translation>Geschwindigkeit des angetriebenen Kolbens; &gt; 0 beim Start treibt ihn ab t = 0 ins Gas.</translation>
    </message>
    <message>
        <source>Steps after a reset or an edit before the fields are averaged.</source>
        <translation>Schritte nach einem Zurücksetzen oder einer Änderung, bevor die Felder gemittelt werden.</translation>
    </message>
    <message>
        <source>Stream speed</source>
        <translation>Anströmgeschwindigkeit</translation>
    </message>
    <message>
        <source>Stream temperature</source>
        <translation>Anströmtemperatur</translation>
    </message>
    <message>
        <source>Temperature T_x</source>
        <translation>Temperatur T_x</translation>
    </message>
    <message>
        <source>Temperature T_y</source>
        <translation>Temperatur T_y</translation>
    </message>
    <message>
        <source>Temperature [K]</source>
        <translation>Temperatur [K]</translation>
    </message>
    <message>
        <source>Temperature of diffuse bodies.</source>
        <translation>Temperatur diffuser Körper.</translation>
    </message>
    <message>
        <source>Temperature of the diffuse sides.</source>
        <translation>Temperatur der diffusen Seiten.</translation>
    </message>
    <message>
        <source>Temperature of the free stream.</source>
        <translation>Temperatur der freien Anströmung.</translation>
    </message>
    <message>
        <source>The left side becomes a specular piston that can be driven to the right (a shock tube).</source>
        <translation>Die linke Seite wird zu einem spiegelnden Kolben, der nach rechts getrieben werden kann (ein Stoßrohr).</translation>
    </message>
    <message>
        <source>The run stops after this many steps; 0 runs on.</source>
        <translation>Der Lauf hält nach so vielen Schritten an; 0 läuft weiter.</translation>
    </message>
    <message>
        <source>Tool speed</source>
        <translation>Werkzeuggeschwindigkeit</translation>
    </message>
    <message>
        <source>Top side</source>
        <translation>Obere Seite</translation>
    </message>
    <message>
        <source>Top wall speed</source>
        <translation>Geschwindigkeit der oberen Wand</translation>
    </message>
    <message>
        <source>VHS reference diameter (argon: 4.17e-10).</source>
        <translation>VHS-Referenzdurchmesser (Argon: 4.17e-10).</translation>
    </message>
    <message>
        <source>Velocity of the free stream along +x.</source>
        <translation>Geschwindigkeit der freien Anströmung entlang +x.</translation>
    </message>
    <message>
        <source>Velocity u_x</source>
        <translation>Geschwindigkeit u_x</translation>
    </message>
    <message>
        <source>Velocity u_y</source>
        <translation>Geschwindigkeit u_y</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <source>Viscosity index: 0.5 hard sphere, 1 Maxwell, argon 0.81.</source>
        <translation>Viskositätsindex: 0,5 harte Kugeln, 1 Maxwell, Argon 0,81.</translation>
    </message>
    <message>
        <source>Wall temperature</source>
        <translation>Wandtemperatur</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>all molecules</source>
        <translation>alle Moleküle</translation>
    </message>
    <message>
        <source>collisions</source>
        <translation>Stöße</translation>
    </message>
    <message>
        <source>collisions per step</source>
        <translation>Stöße je Schritt</translation>
    </message>
    <message>
        <source>diffuse: molecules leave at the body temperature; specular: they are mirrored.</source>
        <translation>diffuse: Moleküle verlassen den Körper mit seiner Temperatur; specular: sie werden gespiegelt.</translation>
    </message>
    <message>
        <source>drag</source>
        <translation>Widerstand</translation>
    </message>
    <message>
        <source>drag [N/m]</source>
        <translation>Widerstand [N/m]</translation>
    </message>
    <message>
        <source>drag, window mean</source>
        <translation>Widerstand, Fenstermittel</translation>
    </message>
    <message>
        <source>empty: vacuum; stream: the free stream everywhere; rest: the free-stream gas at rest.</source>
        <translation>empty: Vakuum; stream: überall die freie Anströmung; rest: das Gas der Anströmung in Ruhe.</translation>
    </message>
    <message>
        <source>inflow: the free stream enters; outflow: vacuum; specular: a mirror; diffuse: a wall at the wall temperature; periodic: wraps to the opposite side.</source>
        <translation>inflow: die freie Anströmung tritt ein; outflow: Vakuum; specular: ein Spiegel; diffuse: eine Wand mit der Wandtemperatur; periodic: weiter auf der Gegenseite.</translation>
    </message>
    <message>
        <source>lift</source>
        <translation>Auftrieb</translation>
    </message>
    <message>
        <source>lift [N/m]</source>
        <translation>Auftrieb [N/m]</translation>
    </message>
    <message>
        <source>lift, window mean</source>
        <translation>Auftrieb, Fenstermittel</translation>
    </message>
    <message>
        <source>molecules</source>
        <translation>Moleküle</translation>
    </message>
    <message>
        <source>m⁻³</source>
        <translation>m⁻³</translation>
    </message>
    <message>
        <source>particles, or a sampled field as a colour map.</source>
        <translation>particles, oder ein gemitteltes Feld als Farbkarte.</translation>
    </message>
    <message>
        <source>inverse-root: σ = 1e-18 c_r^-1/2 m²; hard-sphere: σ = π d²; vhs: variable hard sphere (d_ref, T_ref, ω); maxwell: σ c_r constant.</source>
        <translation>inverse-root: σ = 1e-18 c_r^-1/2 m²; hard-sphere: σ = π d²; vhs: variable harte Kugeln (d_ref, T_ref, ω); maxwell: σ c_r konstant.</translation>
    </message>
    <message>
        <source>simulated molecules</source>
        <translation>simulierte Moleküle</translation>
    </message>
    <message>
        <source>Not sampled yet: the fields appear after the start-up steps</source>
        <translation>Noch nicht abgetastet: die Felder erscheinen nach den Anlaufschritten</translation>
    </message>
    <message>
        <source>SI</source>
        <translation>SI</translation>
    </message>
    <message>
        <source>length L, time T, mass M; energies and kT in M·L²/T²</source>
        <translation>Länge L, Zeit T, Masse M; Energien und kT in M·L²/T²</translation>
    </message>
    <message>
        <source>length L, time s, unit particle mass; gravity in L/s²</source>
        <translation>Länge L, Zeit s, Teilchenmasse 1; Schwerkraft in L/s²</translation>
    </message>
    <message>
        <source>length m, time s, mass kg, temperature K; molecular mass in u</source>
        <translation>Länge m, Zeit s, Masse kg, Temperatur K; Molekülmasse in u</translation>
    </message>
    <message>
        <source>length m, time s, mass kg, temperature K; molecular mass in u; forces and F_N per m of depth</source>
        <translation>Länge m, Zeit s, Masse kg, Temperatur K; Molekülmasse in u; Kräfte und F_N je m Tiefe</translation>
    </message>
    <message>
        <source>mixed (L, s)</source>
        <translation>gemischt (L, s)</translation>
    </message>
    <message>
        <source>reduced (L, T, M)</source>
        <translation>reduziert (L, T, M)</translation>
    </message>
    <message>
        <source>%</source>
        <translation>%</translation>
    </message>
    <message>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <source>N/m</source>
        <translation>N/m</translation>
    </message>
    <message>
        <source>P</source>
        <translation>P</translation>
    </message>
    <message>
        <source>Tₓ</source>
        <translation>Tₓ</translation>
    </message>
    <message>
        <source>T⊥</source>
        <translation>T⊥</translation>
    </message>
    <message>
        <source>collisions per particle</source>
        <translation>Stöße pro Teilchen</translation>
    </message>
    <message>
        <source>density error</source>
        <translation>Dichtefehler</translation>
    </message>
    <message>
        <source>step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>t</source>
        <translation>t</translation>
    </message>
    <message>
        <source>worst density error</source>
        <translation>größter Dichtefehler</translation>
    </message>
    <message>
        <source>µs</source>
        <translation>µs</translation>
    </message>
    <message>
        <source>2d</source>
        <translation>2D</translation>
    </message>
    <message>
        <source>3d</source>
        <translation>3D</translation>
    </message>
    <message>
        <source>Sampling window</source>
        <translation>Mittelungsfenster</translation>
    </message>
    <message>
        <source>The fields and mean forces show the most recent steps only (between half and all of this many), so a moving shock shows where it is; 0: every step since sampling started, for a steady flow.</source>
        <translation>Felder und mittlere Kräfte zeigen nur die jüngsten Schritte (zwischen der Hälfte und allen davon), damit ein laufender Stoß dort erscheint, wo er gerade ist; 0: jeder Schritt seit Beginn der Mittelung, für eine stationäre Strömung.</translation>
    </message>
    <message>
        <source>all-pairs</source>
        <translation>alle Paare</translation>
    </message>
    <message>
        <source>bkw</source>
        <translation>BKW</translation>
    </message>
    <message>
        <source>cell-list</source>
        <translation>Zellliste</translation>
    </message>
    <message>
        <source>density</source>
        <translation>Dichte</translation>
    </message>
    <message>
        <source>diffuse</source>
        <translation>diffus</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>leer</translation>
    </message>
    <message>
        <source>explicit-euler</source>
        <translation>explizites Euler</translation>
    </message>
    <message>
        <source>fixed-speed</source>
        <translation>feste Geschwindigkeit</translation>
    </message>
    <message>
        <source>forest-ruth</source>
        <translation>Forest-Ruth</translation>
    </message>
    <message>
        <source>hard-sphere</source>
        <translation>harte Kugeln</translation>
    </message>
    <message>
        <source>inflow</source>
        <translation>Zustrom</translation>
    </message>
    <message>
        <source>inverse-root</source>
        <translation>σ ∝ 1/√c_r</translation>
    </message>
    <message>
        <source>lattice</source>
        <translation>Gitter</translation>
    </message>
    <message>
        <source>mach</source>
        <translation>Mach-Zahl</translation>
    </message>
    <message>
        <source>maxwell</source>
        <translation>Maxwell-Moleküle</translation>
    </message>
    <message>
        <source>maxwell-boltzmann</source>
        <translation>Maxwell-Boltzmann</translation>
    </message>
    <message>
        <source>maxwellian</source>
        <translation>Maxwell-Verteilung</translation>
    </message>
    <message>
        <source>outflow</source>
        <translation>Abstrom</translation>
    </message>
    <message>
        <source>particles</source>
        <translation>Teilchen</translation>
    </message>
    <message>
        <source>periodic</source>
        <translation>periodisch</translation>
    </message>
    <message>
        <source>random</source>
        <translation>zufällig</translation>
    </message>
    <message>
        <source>reflecting</source>
        <translation>reflektierend</translation>
    </message>
    <message>
        <source>rest</source>
        <translation>ruhend</translation>
    </message>
    <message>
        <source>rk4</source>
        <translation>Runge-Kutta 4</translation>
    </message>
    <message>
        <source>spawn-lattice</source>
        <translation>aus dem Startgitter</translation>
    </message>
    <message>
        <source>specular</source>
        <translation>spiegelnd</translation>
    </message>
    <message>
        <source>stream</source>
        <translation>Anströmung</translation>
    </message>
    <message>
        <source>symplectic-euler</source>
        <translation>symplektisches Euler</translation>
    </message>
    <message>
        <source>temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <source>thermal</source>
        <translation>thermisch</translation>
    </message>
    <message>
        <source>two-beams</source>
        <translation>zwei Strahlen</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>velocity-verlet</source>
        <translation>Velocity-Verlet</translation>
    </message>
    <message>
        <source>vhs</source>
        <translation>VHS</translation>
    </message>
    <message>
        <source>A: kT = %1, KS distance %2</source>
        <translation>A: kT = %1, KS-Abstand %2</translation>
    </message>
    <message>
        <source>B: kT = %1, KS distance %2</source>
        <translation>B: kT = %1, KS-Abstand %2</translation>
    </message>
    <message>
        <source>T = %1 K, u_x = %2 m/s, %3 collisions each</source>
        <translation>T = %1 K, u_x = %2 m/s, %3 Stöße je Teilchen</translation>
    </message>
    <message>
        <source>beam %1 (%2 m/s)</source>
        <translation>Strahl %1 (%2 m/s)</translation>
    </message>
    <message>
        <source>kT = %1, KS distance %2</source>
        <translation>kT = %1, KS-Abstand %2</translation>
    </message>
    <message>
        <source>the whole domain: %1 molecules</source>
        <translation>das ganze Gebiet: %1 Moleküle</translation>
    </message>
    <message>
        <source>the whole domain: %1 molecules (free stream, shock layer and wake together)</source>
        <translation>das ganze Gebiet: %1 Moleküle (Anströmung, Stoßschicht und Nachlauf zusammen)</translation>
    </message>
    <message>
        <source>cells are %1 free-stream mean free paths wide (λ = %2 m), above λ/%3: use cells_x ≥ %4 and cells_y ≥ %5</source>
        <translation>die Zellen sind %1 freie Weglängen der Anströmung breit (λ = %2 m), mehr als λ/%3: cells_x ≥ %4 und cells_y ≥ %5 wählen</translation>
    </message>
    <message>
        <source>%1 particles exceed the limit of %2</source>
        <translation>%1 Teilchen überschreiten die Grenze von %2</translation>
    </message>
    <message>
        <source>a DSMC cell needs at least %1 particles to collide ({1} + {2} = %2)</source>
        <translation>eine DSMC-Zelle braucht mindestens %1 Teilchen für Stöße ({1} + {2} = %2)</translation>
    </message>
    <message>
        <source>the BKW solution is for %1 velocity components; use %2, or another initial state</source>
        <translation>die BKW-Lösung gilt für %1 Geschwindigkeitskomponenten; %2 verwenden oder einen anderen Anfangszustand</translation>
    </message>
    <message>
        <source>the disks cover %1 % of the %2 × %3 box; at most %4 % fits (fewer or smaller disks, or a larger box)</source>
        <translation>die Scheiben bedecken %1 % der %2 × %3 großen Box; höchstens %4 % passen (weniger oder kleinere Scheiben oder eine größere Box)</translation>
    </message>
    <message>
        <source>the free stream collides %1 times per molecule and step, more than a step can do (%2); use {1} ≤ %3 s</source>
        <translation>die Anströmung stößt %1-mal je Molekül und Schritt, mehr als ein Schritt leisten kann (%2); {1} ≤ %3 s verwenden</translation>
    </message>
    <message>
        <source>the free stream fills the domain with %1 molecules, more than the %2 this machine&apos;s memory holds now; raise {1} to at least %3</source>
        <translation>die Anströmung füllt das Gebiet mit %1 Molekülen, mehr als die %2, die der Speicher dieses Rechners jetzt fasst; {1} auf mindestens %3 erhöhen</translation>
    </message>
    <message>
        <source>the free stream fills the domain with %1 molecules, more than the limit of %2; raise {1} to at least %3</source>
        <translation>die Anströmung füllt das Gebiet mit %1 Molekülen, mehr als die Grenze von %2; {1} auf mindestens %3 erhöhen</translation>
    </message>
    <message>
        <source>the initial block holds %1 particles, more than {1} = %2</source>
        <translation>der Anfangsblock enthält %1 Teilchen, mehr als {1} = %2</translation>
    </message>
    <message>
        <source>the initial block must lie inside the box [%1, %2] × [%3, %4]</source>
        <translation>der Anfangsblock muss in der Box [%1; %2] × [%3; %4] liegen</translation>
    </message>
    <message>
        <source>the piston replaces the left side, which is periodic; make {1} and {2} non-periodic or switch {3} off</source>
        <translation>der Kolben ersetzt die linke Seite, die periodisch ist; {1} und {2} nicht periodisch machen oder {3} ausschalten</translation>
    </message>
    <message>
        <source>{1} + {2} = %1 exceeds {3} = %2</source>
        <translation>{1} + {2} = %1 übersteigt {3} = %2</translation>
    </message>
    <message>
        <source>{1} = %1 is too large for the %2 × %3 box: it needs at least %4 h across</source>
        <translation>{1} = %1 ist zu groß für die %2 × %3 große Box: sie braucht mindestens %4 h Breite</translation>
    </message>
    <message>
        <source>{1} = %1 is too large: a particle does not fit in the %2 × %3 box</source>
        <translation>{1} = %1 ist zu groß: ein Teilchen passt nicht in die %2 × %3 große Box</translation>
    </message>
    <message>
        <source>{1} and {2} must both be periodic or neither</source>
        <translation>{1} und {2} müssen beide periodisch sein oder keiner</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] K)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] K)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] L)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] L)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] L/T)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] L/T)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] L/T²)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] L/T²)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] L/s)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] L/s)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] L/s²)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] L/s²)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] M)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] M)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] M/T²)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] M/T²)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] M·L²/T²)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] M·L²/T²)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] T)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] T)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] d)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] d)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] except %4 T)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] außer %4 T)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] m)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] m)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] m/s)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] m/s)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] m³)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] m³)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] m³/s)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] m³/s)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] m⁻³)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] m⁻³)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] s)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] s)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] steps)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] Schritte)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] u)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] u)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] × rms speed)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] × rms-Geschwindigkeit)</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] × √(g H))</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] × √(g H))</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3])</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3])</translation>
    </message>
    <message>
        <source>{1} lets the run hold about %1 GiB of memory, more than the %2 GiB this machine can give it now; use {2} ≤ %3</source>
        <translation>mit {1} braucht der Lauf etwa %1 GiB Speicher, mehr als die %2 GiB, die dieser Rechner ihm jetzt geben kann; {2} ≤ %3 verwenden</translation>
    </message>
    <message>
        <source>{1} lets the run hold about %1 GiB of memory, more than the %2 MiB this machine can give it now; use at most %3 particles ({2} + {3})</source>
        <translation>mit {1} braucht der Lauf etwa %1 GiB Speicher, mehr als die %2 MiB, die dieser Rechner ihm jetzt geben kann; höchstens %3 Teilchen verwenden ({2} + {3})</translation>
    </message>
    <message>
        <source>{1} lets the run hold about %1 GiB of memory, more than the %2 MiB this machine can give it now; use {2} ≤ %3</source>
        <translation>mit {1} braucht der Lauf etwa %1 GiB Speicher, mehr als die %2 MiB, die dieser Rechner ihm jetzt geben kann; {2} ≤ %3 verwenden</translation>
    </message>
    <message>
        <source>{1} lets the run hold about %1 MiB of memory, more than the %2 MiB this machine can give it now; use at most %3 cells ({2} × {3})</source>
        <translation>mit {1} braucht der Lauf etwa %1 MiB Speicher, mehr als die %2 MiB, die dieser Rechner ihm jetzt geben kann; höchstens %3 Zellen verwenden ({2} × {3})</translation>
    </message>
    <message>
        <source>{1} must be an integer, got %1 (allowed: [%2, %3] steps)</source>
        <translation>{1} muss eine ganze Zahl sein, nicht %1 (erlaubt: [%2; %3] Schritte)</translation>
    </message>
    <message>
        <source>{1} must be an integer, got %1 (allowed: [%2, %3])</source>
        <translation>{1} muss eine ganze Zahl sein, nicht %1 (erlaubt: [%2; %3])</translation>
    </message>
    <message>
        <source>{1} must not be %1 (allowed: [%2, %3] except %4 T)</source>
        <translation>{1} darf nicht %1 sein (erlaubt: [%2; %3] außer %4 T)</translation>
    </message>
    <message>
        <source>{1} × {2} = %1 cells exceed the limit of %2</source>
        <translation>{1} × {2} = %1 Zellen überschreiten die Grenze von %2</translation>
    </message>
    <message>
        <source>ν Δt = %1 collisions per particle and step (%2 candidate pairs a step) is more than the %3 a step can do in reasonable time; use {1} ≤ %4 s (now %5) or {2} ≤ %6 (now %7) to keep it below Bird&apos;s guideline of %8</source>
        <translation>ν Δt = %1 Stöße je Teilchen und Schritt (%2 Kandidatenpaare je Schritt) sind mehr als die %3, die ein Schritt in vertretbarer Zeit schafft; {1} ≤ %4 s (jetzt %5) oder {2} ≤ %6 (jetzt %7) verwenden, um unter Birds Richtwert von %8 zu bleiben</translation>
    </message>
    <message>
        <source>{1} lets the run hold about %1 GiB of memory, more than the %2 KiB this machine can give it now; use at most %3 disks ({2} + {3}, and {4})</source>
        <translation>mit {1} braucht der Lauf etwa %1 GiB Speicher, mehr als die %2 KiB, die dieser Rechner ihm jetzt geben kann; höchstens %3 Scheiben verwenden ({2} + {3}, und {4})</translation>
    </message>
    <message>
        <source>{1} lets the run hold about %1 GiB of memory, more than the %2 KiB this machine can give it now; use at most %3 particles ({2} + {3})</source>
        <translation>mit {1} braucht der Lauf etwa %1 GiB Speicher, mehr als die %2 KiB, die dieser Rechner ihm jetzt geben kann; höchstens %3 Teilchen verwenden ({2} + {3})</translation>
    </message>
    <message>
        <source>{1} lets the run hold about %1 GiB of memory, more than the %2 KiB this machine can give it now; use {2} ≤ %3</source>
        <translation>mit {1} braucht der Lauf etwa %1 GiB Speicher, mehr als die %2 KiB, die dieser Rechner ihm jetzt geben kann; {2} ≤ %3 verwenden</translation>
    </message>
    <message>
        <source>{1} lets the run hold about %1 KiB of memory, more than the %2 KiB this machine can give it now; use at most %3 cells ({2} × {3})</source>
        <translation>mit {1} braucht der Lauf etwa %1 KiB Speicher, mehr als die %2 KiB, die dieser Rechner ihm jetzt geben kann; höchstens %3 Zellen verwenden ({2} × {3})</translation>
    </message>
    <message>
        <source>{1} lets the run hold about %1 KiB of memory, more than the %2 KiB this machine can give it now; use at most %3 particles ({2} + {3})</source>
        <translation>mit {1} braucht der Lauf etwa %1 KiB Speicher, mehr als die %2 KiB, die dieser Rechner ihm jetzt geben kann; höchstens %3 Teilchen verwenden ({2} + {3})</translation>
    </message>
    <message>
        <source>{1} lets the run hold about %1 MiB of memory, more than the %2 KiB this machine can give it now; use at most %3 cells ({2} × {3})</source>
        <translation>mit {1} braucht der Lauf etwa %1 MiB Speicher, mehr als die %2 KiB, die dieser Rechner ihm jetzt geben kann; höchstens %3 Zellen verwenden ({2} × {3})</translation>
    </message>
    <message>
        <source>{1} lets the run hold about %1 MiB of memory, more than the %2 KiB this machine can give it now; use at most %3 disks ({2} + {3}, and {4})</source>
        <translation>mit {1} braucht der Lauf etwa %1 MiB Speicher, mehr als die %2 KiB, die dieser Rechner ihm jetzt geben kann; höchstens %3 Scheiben verwenden ({2} + {3}, und {4})</translation>
    </message>
    <message>
        <source>{1} lets the run hold about %1 MiB of memory, more than the %2 KiB this machine can give it now; use {2} ≤ %3</source>
        <translation>mit {1} braucht der Lauf etwa %1 MiB Speicher, mehr als die %2 KiB, die dieser Rechner ihm jetzt geben kann; {2} ≤ %3 verwenden</translation>
    </message>
    <message>
        <source>{1} lets the run hold about %1 MiB of memory, more than the %2 MiB this machine can give it now; use {2} ≤ %3</source>
        <translation>mit {1} braucht der Lauf etwa %1 MiB Speicher, mehr als die %2 MiB, die dieser Rechner ihm jetzt geben kann; {2} ≤ %3 verwenden</translation>
    </message>
    <message>
        <source>{1} is out of range: %1 (allowed: [%2, %3] × |g| Δt)</source>
        <translation>{1} liegt außerhalb des Bereichs: %1 (erlaubt: [%2; %3] × |g| Δt)</translation>
    </message>
    <message>
        <source>Adhesion β</source>
        <translation>Adhäsion β</translation>
    </message>
    <message>
        <source>Attraction between neighbours, the origin of surface tension: it holds the free surface together where nothing else does (gravity switched off). The pull of one neighbour at h/2; 0: off, as in the paper and the write-up.</source>
        <translation>Anziehung zwischen Nachbarn, der Ursprung der Oberflächenspannung: Sie hält die freie Oberfläche zusammen, wo nichts anderes es tut (Schwerkraft ausgeschaltet). Der Zug eines Nachbarn im Abstand h/2; 0: aus, wie im Artikel und im Original.</translation>
    </message>
    <message>
        <source>Cohesion γ</source>
        <translation>Kohäsion γ</translation>
    </message>
    <message>
        <source>Pull of the walls and obstacles on the fluid within h of them, so it wets them instead of balling up under cohesion. The pull at 3h/4; 0: off, as in the paper and the write-up.</source>
        <translation>Zug der Wände und Hindernisse auf die Flüssigkeit im Abstand bis h, sodass sie sie benetzt, statt sich unter der Kohäsion zusammenzuballen. Der Zug im Abstand 3h/4; 0: aus, wie im Artikel und im Original.</translation>
    </message>
</context>
<context>
    <name>pl::ui::Allowed</name>
    <message>
        <source>%1 except 0</source>
        <translation>%1 außer 0</translation>
    </message>
    <message>
        <source>true or false</source>
        <translation>wahr oder falsch</translation>
    </message>
    <message>
        <source>one of: %1</source>
        <translation>eins von: %1</translation>
    </message>
</context>
<context>
    <name>pl::ui::AppRecorder</name>
    <message>
        <source>the experiment was replaced</source>
        <translation>das Experiment wurde ersetzt</translation>
    </message>
    <message>
        <source>the model stopped</source>
        <translation>das Modell ist stehen geblieben</translation>
    </message>
    <message>
        <source>Nothing to record.</source>
        <translation>Es gibt nichts aufzunehmen.</translation>
    </message>
    <message>
        <source>%1 (%2 s of clip)</source>
        <translation>%1 (%2 s Clip)</translation>
    </message>
    <message>
        <source>Clip saved, %1</source>
        <translation>Clip gespeichert, %1</translation>
    </message>
    <message>
        <source>The clip ended early (%1); saved %2</source>
        <translation>Der Clip endete vorzeitig (%1); gespeichert: %2</translation>
    </message>
    <message>
        <source>The previous clip is still being finished.</source>
        <translation>Der vorige Clip wird noch fertiggestellt.</translation>
    </message>
    <message>
        <source>The scene has no plot &apos;%1&apos;.</source>
        <translation>Die Szene hat kein Diagramm „%1“.</translation>
    </message>
    <message>
        <source>Encoding cancelled; saved the frames encoded, %1</source>
        <translation>Kodieren abgebrochen; die kodierten Bilder sind gespeichert, %1</translation>
    </message>
</context>
<context>
    <name>pl::ui::Autosave</name>
    <message>
        <source>Cannot create %1</source>
        <translation>%1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>Restore the last experiment?</source>
        <translation>Letztes Experiment wiederherstellen?</translation>
    </message>
    <message>
        <source>ParticleLab did not close normally. Its last experiment was saved %1. Restore it?</source>
        <translation>ParticleLab wurde nicht normal beendet. Das letzte Experiment wurde am %1 gesichert. Wiederherstellen?</translation>
    </message>
    <message>
        <source>Cannot restore the experiment</source>
        <translation>Das Experiment kann nicht wiederhergestellt werden</translation>
    </message>
</context>
<context>
    <name>pl::ui::BenchmarkDialog</name>
    <message>
        <source>Benchmark this machine</source>
        <translation>Diesen Rechner vermessen</translation>
    </message>
    <message>
        <source>particles N</source>
        <translation>Teilchen N</translation>
    </message>
    <message>
        <source>particle-steps per second</source>
        <translation>Teilchenschritte pro Sekunde</translation>
    </message>
    <message>
        <source>Times the scenes at growing N on the CPU and, where OpenGL 4.3 is available, on the GPU. Right-click the plot to export it.</source>
        <translation>Misst die Szenen bei wachsendem N auf der CPU und, wo OpenGL 4.3 verfügbar ist, auf der GPU. Rechtsklick auf das Diagramm exportiert es.</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportieren…</translation>
    </message>
    <message>
        <source>Stopped after %1 of %2 measurements.</source>
        <translation>Angehalten nach %1 von %2 Messungen.</translation>
    </message>
    <message>
        <source>Done: %1 measurements. Right-click the plot to save it or its data.</source>
        <translation>Fertig: %1 Messungen. Rechtsklick auf das Diagramm speichert es oder seine Daten.</translation>
    </message>
    <message>
        <source>Timing %1 with %2 particles on the %3…</source>
        <translation>Zeitmessung: %1 mit %2 Teilchen auf der %3…</translation>
    </message>
    <message>
        <source>GPU</source>
        <translation>GPU</translation>
    </message>
    <message>
        <source>CPU</source>
        <translation>CPU</translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation>%1 fehlgeschlagen: %2</translation>
    </message>
</context>
<context>
    <name>pl::ui::DistributionPlot</name>
    <message>
        <source>Average over</source>
        <translation>Mitteln über</translation>
    </message>
    <message>
        <source>Time-averages the bars over the last samples (about 20 per second of running)</source>
        <translation>Mittelt die Balken zeitlich über die letzten Stichproben (etwa 20 pro Sekunde Laufzeit)</translation>
    </message>
    <message>
        <source>probability density</source>
        <translation>Wahrscheinlichkeitsdichte</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>gemessen</translation>
    </message>
    <message>
        <source>Maxwell–Boltzmann</source>
        <translation>Maxwell–Boltzmann</translation>
    </message>
    <message>
        <source>%1 (theory)</source>
        <translation>%1 (Theorie)</translation>
    </message>
    <message numerus="yes">
        <source>%n sample(s)</source>
        <comment>a spin box&apos;s value and unit</comment>
        <translation>
            <numerusform>%n Stichprobe</numerusform>
            <numerusform>%n Stichproben</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pl::ui::DsmcPage</name>
    <message>
        <source>Maxwell molecules relaxing from the BKW start for 6 mean collision times, at each number of particles in the cell and collision probability ν dt per step. The error is the rms distance of the 4th and 6th moments from the exact BKW curves. In one homogeneous cell the noise of N particles (∝ 1/√N) outweighs the time step, and the cost is the number of collisions.</source>
        <translation>Maxwell-Moleküle relaxieren vom BKW-Start aus über 6 mittlere Stoßzeiten, für jede Teilchenzahl in der Zelle und jede Stoßwahrscheinlichkeit ν dt pro Schritt. Der Fehler ist der quadratisch gemittelte Abstand des 4. und 6. Moments von den exakten BKW-Kurven. In einer homogenen Zelle überwiegt das Rauschen von N Teilchen (∝ 1/√N) den Zeitschritt, und die Kosten sind die Zahl der Stöße.</translation>
    </message>
    <message>
        <source>wall time of the run [s]</source>
        <translation>Rechenzeit des Laufs [s]</translation>
    </message>
    <message>
        <source>rms moment error</source>
        <translation>rms-Fehler der Momente</translation>
    </message>
    <message>
        <source>moment error</source>
        <translation>Momentenfehler</translation>
    </message>
    <message>
        <source>s per run</source>
        <translation>s pro Lauf</translation>
    </message>
    <message>
        <source>ν dt = %1</source>
        <translation>ν dt = %1</translation>
    </message>
    <message>
        <source>ν dt = %1: error %2 at %3 particles, %4 at %5</source>
        <translation>ν dt = %1: Fehler %2 bei %3 Teilchen, %4 bei %5</translation>
    </message>
    <message>
        <source>DSMC sweep</source>
        <translation>DSMC-Parameterstudie</translation>
    </message>
    <message>
        <source>load a DSMC experiment to apply</source>
        <translation>zum Übernehmen ein DSMC-Experiment laden</translation>
    </message>
    <message>
        <source>measured for Maxwell molecules: the current cell uses %1</source>
        <translation>für Maxwell-Moleküle gemessen: die aktuelle Zelle verwendet %1</translation>
    </message>
    <message>
        <source>the sweep counts one population of particles; the current cell has two beams</source>
        <translation>die Parameterstudie zählt eine Teilchenpopulation; die aktuelle Zelle hat zwei Strahlen</translation>
    </message>
    <message>
        <source>no DSMC experiment is open</source>
        <translation>kein DSMC-Experiment geöffnet</translation>
    </message>
</context>
<context>
    <name>pl::ui::EchoPage</name>
    <message>
        <source>64 disks in a periodic box run n steps forward, reverse and run n steps back. Chaos amplifies round-off exponentially; bit-reversible integers return exactly.</source>
        <translation>64 Scheiben in einem periodischen Behälter laufen n Schritte vorwärts, kehren um und laufen n Schritte zurück. Chaos verstärkt Rundungsfehler exponentiell; bitgenau umkehrbare Ganzzahlen kehren exakt zurück.</translation>
    </message>
    <message>
        <source>steps out and back, n</source>
        <translation>Schritte hin und zurück, n</translation>
    </message>
    <message>
        <source>rms return error [L]</source>
        <translation>rms-Rückkehrfehler [L]</translation>
    </message>
    <message>
        <source>double</source>
        <translation>double</translation>
    </message>
    <message>
        <source>float</source>
        <translation>float</translation>
    </message>
    <message>
        <source>n = %1: double %2, float %3, integers %4</source>
        <translation>n = %1: double %2, float %3, Ganzzahlen %4</translation>
    </message>
    <message>
        <source>exactly 0</source>
        <translation>exakt 0</translation>
    </message>
    <message>
        <source>Loschmidt echo</source>
        <translation>Loschmidt-Echo</translation>
    </message>
</context>
<context>
    <name>pl::ui::ExperimentDocument</name>
    <message>
        <source>Cannot open preset</source>
        <translation>Vorlage kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>Cannot create experiment</source>
        <translation>Experiment kann nicht erstellt werden</translation>
    </message>
    <message>
        <source>Unknown scene &apos;%1&apos;.</source>
        <translation>Unbekannte Szene „%1“.</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <source>Save preset</source>
        <translation>Vorlage speichern</translation>
    </message>
    <message>
        <source>Experiments (*.particlelab);;Presets (*.json)</source>
        <translation>Experimente (*.particlelab);;Vorlagen (*.json)</translation>
    </message>
    <message>
        <source>Cannot save preset</source>
        <translation>Vorlage kann nicht gespeichert werden</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>The experiment &apos;%1&apos; has changes. Save them as a preset?</source>
        <translation>Das Experiment „%1“ wurde geändert. Änderungen als Vorlage speichern?</translation>
    </message>
    <message>
        <source>restored</source>
        <translation>wiederhergestellt</translation>
    </message>
    <message>
        <source>Cannot save snapshot</source>
        <translation>Momentaufnahme kann nicht gespeichert werden</translation>
    </message>
</context>
<context>
    <name>pl::ui::ExportImageDialog</name>
    <message>
        <source>Image size</source>
        <translation>Bildgröße</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source> DPI</source>
        <translation> DPI</translation>
    </message>
    <message>
        <source>Keep the plot&apos;s proportions</source>
        <translation>Seitenverhältnis des Plots beibehalten</translation>
    </message>
    <message>
        <source>Resolution recorded in the file</source>
        <translation>In der Datei vermerkte Auflösung</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <source>Resolution</source>
        <translation>Auflösung</translation>
    </message>
    <message>
        <source>The PNG has exactly the pixels above; a higher DPI draws text and lines larger on them</source>
        <translation>Das PNG hat genau die Pixel oben; mehr DPI zeichnen Text und Linien darauf größer</translation>
    </message>
</context>
<context>
    <name>pl::ui::FluidPage</name>
    <message>
        <source>A 5 × 10 dam break (about 300 particles) for 1 s of simulated time at each dt and number of solver iterations. Over-compressed: the mean density error stayed above 1 %. Exploded: the solver diverged, or after half the run the fluid still held more kinetic energy than the fall through the box can release. Right: the density error against what it cost.</source>
        <translation>Ein 5 × 10-Dammbruch (etwa 300 Teilchen) über 1 s simulierte Zeit für jedes dt und jede Zahl von Löser-Iterationen. Überkomprimiert: Der mittlere Dichtefehler blieb über 1 %. Explodiert: Der Löser divergierte, oder nach der halben Laufzeit hatte die Flüssigkeit noch mehr kinetische Energie, als der Fall durch den Behälter freisetzen kann. Rechts: der Dichtefehler gegen seine Kosten.</translation>
    </message>
    <message>
        <source>time step dt [s]</source>
        <translation>Zeitschritt dt [s]</translation>
    </message>
    <message>
        <source>solver iterations</source>
        <translation>Löser-Iterationen</translation>
    </message>
    <message>
        <source>wall time per simulated second [s]</source>
        <translation>Rechenzeit pro simulierter Sekunde [s]</translation>
    </message>
    <message>
        <source>mean density error</source>
        <translation>mittlerer Dichtefehler</translation>
    </message>
    <message>
        <source>max density error</source>
        <translation>größter Dichtefehler</translation>
    </message>
    <message>
        <source>Error:</source>
        <translation>Fehler:</translation>
    </message>
    <message>
        <source>density error</source>
        <translation>Dichtefehler</translation>
    </message>
    <message>
        <source>no experiment is open</source>
        <translation>kein Experiment geöffnet</translation>
    </message>
    <message>
        <source>load a fluid experiment to apply</source>
        <translation>zum Übernehmen ein Flüssigkeitsexperiment laden</translation>
    </message>
    <message>
        <source>current fluid</source>
        <translation>aktuelle Flüssigkeit</translation>
    </message>
    <message>
        <source>dt = %1: %2 of %3 settings ran through</source>
        <translation>dt = %1: %2 von %3 Einstellungen liefen durch</translation>
    </message>
    <message>
        <source>Fluid sweep</source>
        <translation>Flüssigkeits-Parameterstudie</translation>
    </message>
    <message>
        <source>dt = %1</source>
        <translation>dt = %1</translation>
    </message>
</context>
<context>
    <name>pl::ui::GasSweepPage</name>
    <message>
        <source>Each integrator over a range of dt for the same simulated time. The harmonic pair (two disks pressed together and released) has an exact solution; the current gas is compared with a Forest–Ruth run at 1/16 of its step over 64 of its steps. Lower and further left is better; the legend gives each scheme&apos;s measured order.</source>
        <translation>Jeder Integrator über einen Bereich von dt für dieselbe simulierte Zeit. Das harmonische Paar (zwei zusammengedrückte und losgelassene Scheiben) hat eine exakte Lösung; das aktuelle Gas wird mit einem Forest–Ruth-Lauf mit 1/16 seines Schritts über 64 seiner Schritte verglichen. Weiter unten und weiter links ist besser; die Legende nennt die gemessene Ordnung jedes Verfahrens.</translation>
    </message>
    <message>
        <source>Harmonic pair (exact)</source>
        <translation>Harmonisches Paar (exakt)</translation>
    </message>
    <message>
        <source>Current gas (reference run)</source>
        <translation>Aktuelles Gas (Referenzlauf)</translation>
    </message>
    <message>
        <source>position error</source>
        <translation>Ortsfehler</translation>
    </message>
    <message>
        <source>energy error</source>
        <translation>Energiefehler</translation>
    </message>
    <message>
        <source>force evaluations per unit time</source>
        <translation>Kraftauswertungen pro Zeiteinheit</translation>
    </message>
    <message>
        <source>wall time per unit time</source>
        <translation>Rechenzeit pro Zeiteinheit</translation>
    </message>
    <message>
        <source>Start from:</source>
        <translation>Ausgehend von:</translation>
    </message>
    <message>
        <source>Error:</source>
        <translation>Fehler:</translation>
    </message>
    <message>
        <source>Cost:</source>
        <translation>Kosten:</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>no experiment is open</source>
        <translation>kein Experiment geöffnet</translation>
    </message>
    <message>
        <source>the pair&apos;s dt belongs to its own stiffness: sweep the current gas to apply</source>
        <translation>das dt des Paares gehört zu seiner eigenen Steifigkeit: zum Übernehmen das aktuelle Gas untersuchen</translation>
    </message>
    <message>
        <source>load a gas experiment to apply</source>
        <translation>zum Übernehmen ein Gasexperiment laden</translation>
    </message>
    <message>
        <source>Load a gas experiment with disks first, or sweep the harmonic pair.</source>
        <translation>Zuerst ein Gasexperiment mit Scheiben laden oder das harmonische Paar untersuchen.</translation>
    </message>
    <message>
        <source>Reference run done; sweeping the integrators…</source>
        <translation>Referenzlauf fertig; die Integratoren werden untersucht…</translation>
    </message>
    <message>
        <source>%1: measured order %2 (theory %3)%4</source>
        <translation>%1: gemessene Ordnung %2 (Theorie %3)%4</translation>
    </message>
    <message>
        <source>; %1 dt blew up and is not drawn</source>
        <translation>; %1 dt ist explodiert und wird nicht gezeichnet</translation>
    </message>
    <message>
        <source>Integrator sweep</source>
        <translation>Integrator-Parameterstudie</translation>
    </message>
    <message>
        <source>%1 (order %2, theory %3)</source>
        <translation>%1 (Ordnung %2, Theorie %3)</translation>
    </message>
    <message>
        <source>current setting</source>
        <translation>aktuelle Einstellung</translation>
    </message>
</context>
<context>
    <name>pl::ui::LabPage</name>
    <message>
        <source>Run</source>
        <translation>Ausführen</translation>
    </message>
</context>
<context>
    <name>pl::ui::LabRunner</name>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>%1: running…</source>
        <translation>%1: läuft…</translation>
    </message>
    <message>
        <source>A point failed: %1</source>
        <translation>Ein Punkt ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>an unknown error</source>
        <translation>ein unbekannter Fehler</translation>
    </message>
    <message>
        <source>A point failed with an unknown error.</source>
        <translation>Ein Punkt ist mit einem unbekannten Fehler fehlgeschlagen.</translation>
    </message>
    <message>
        <source>Cancelling after the current point…</source>
        <translation>Abbruch nach dem aktuellen Punkt…</translation>
    </message>
    <message>
        <source>%1: cancelled after %2 of %3 points.</source>
        <translation>%1: abgebrochen nach %2 von %3 Punkten.</translation>
    </message>
    <message>
        <source>%1: done; %2 of %3 points failed, the last with: %4</source>
        <translation>%1: fertig; %2 von %3 Punkten fehlgeschlagen, der letzte mit: %4</translation>
    </message>
</context>
<context>
    <name>pl::ui::Language</name>
    <message>
        <source>System default</source>
        <translation>Systemvorgabe</translation>
    </message>
</context>
<context>
    <name>pl::ui::LessonControls</name>
    <message>
        <source>Run</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Piston</source>
        <translation>Kolben</translation>
    </message>
    <message>
        <source>Replace the right wall by a piston</source>
        <translation>Die rechte Wand durch einen Kolben ersetzen</translation>
    </message>
    <message>
        <source>◀ Compress</source>
        <translation>◀ Verdichten</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Expand ▶</source>
        <translation>Entspannen ▶</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <source>Gravity on</source>
        <translation>Schwerkraft an</translation>
    </message>
    <message>
        <source>Pour (hold)</source>
        <translation>Eingießen (halten)</translation>
    </message>
    <message>
        <source>Steps per frame</source>
        <translation>Schritte pro Bild</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>◀ Cool   Heat ▶</source>
        <translation>◀ Kühlen   Heizen ▶</translation>
    </message>
    <message>
        <source>Spawn tool</source>
        <translation>Werkzeug „Erzeugen“</translation>
    </message>
    <message>
        <source>Show</source>
        <translation>Anzeige</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>auto</translation>
    </message>
    <message>
        <source>Add particles where you like: drag a rectangle in the scene to fill it</source>
        <translation>Teilchen hinzufügen, wo man möchte: ein Rechteck in der Szene aufziehen, um es zu füllen</translation>
    </message>
    <message>
        <source>Drag a rectangle in the scene to fill it with particles; a click adds one.</source>
        <translation>Ein Rechteck in der Szene aufziehen, um es mit Teilchen zu füllen; ein Klick fügt eines hinzu.</translation>
    </message>
    <message>
        <source>Restarted with %1 particles at %2 = %3.</source>
        <translation>Neu gestartet mit %1 Teilchen bei %2 = %3.</translation>
    </message>
    <message>
        <source>Particles (restart at this %1)</source>
        <translation>Teilchen (Neustart bei diesem %1)</translation>
    </message>
</context>
<context>
    <name>pl::ui::MainWindow</name>
    <message>
        <source>ParticleLab</source>
        <translation>ParticleLab</translation>
    </message>
    <message>
        <source>The simulation stopped</source>
        <translation>Die Simulation wurde angehalten</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Speed distribution</source>
        <translation>Geschwindigkeitsverteilung</translation>
    </message>
    <message>
        <source>v_x distribution</source>
        <translation>v_x-Verteilung</translation>
    </message>
    <message>
        <source>Methods lab</source>
        <translation>Methodenlabor</translation>
    </message>
    <message>
        <source>%1[*] — ParticleLab</source>
        <translation>%1[*] — ParticleLab</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>GPU</source>
        <translation>GPU</translation>
    </message>
    <message>
        <source>CPU</source>
        <translation>CPU</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;New experiment</source>
        <translation>&amp;Neues Experiment</translation>
    </message>
    <message>
        <source>&amp;Open preset…</source>
        <translation>Vorlage ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Open a preset file</source>
        <translation>Eine Vorlagendatei öffnen</translation>
    </message>
    <message>
        <source>Open preset</source>
        <translation>Vorlage öffnen</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Save preset</source>
        <translation>Vorlage &amp;speichern</translation>
    </message>
    <message>
        <source>Save the experiment as a preset</source>
        <translation>Das Experiment als Vorlage speichern</translation>
    </message>
    <message>
        <source>Save preset &amp;as…</source>
        <translation>Vorlage speichern &amp;unter…</translation>
    </message>
    <message>
        <source>Save the experiment under a new name</source>
        <translation>Das Experiment unter neuem Namen speichern</translation>
    </message>
    <message>
        <source>Save viewport &amp;image…</source>
        <translation>Ansicht als B&amp;ild speichern…</translation>
    </message>
    <message>
        <source>Save what the viewport shows as a PNG</source>
        <translation>Den Inhalt der Simulationsansicht als PNG speichern</translation>
    </message>
    <message>
        <source>Save viewport image</source>
        <translation>Bild der Ansicht speichern</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <source>Cannot save the image</source>
        <translation>Das Bild kann nicht gespeichert werden</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>Close ParticleLab</source>
        <translation>ParticleLab schließen</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>Run or pause the simulation</source>
        <translation>Die Simulation starten oder anhalten</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Advance one time step</source>
        <translation>Einen Zeitschritt weiter</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Restart from the initial state with the current parameters</source>
        <translation>Mit den aktuellen Parametern vom Anfangszustand neu beginnen</translation>
    </message>
    <message>
        <source> Steps per frame </source>
        <translation> Schritte pro Bild </translation>
    </message>
    <message>
        <source>Slower</source>
        <translation>Langsamer</translation>
    </message>
    <message>
        <source>One step per frame less</source>
        <translation>Ein Schritt pro Bild weniger</translation>
    </message>
    <message>
        <source>Faster</source>
        <translation>Schneller</translation>
    </message>
    <message>
        <source>One step per frame more</source>
        <translation>Ein Schritt pro Bild mehr</translation>
    </message>
    <message>
        <source>Reverse time</source>
        <translation>Zeit umkehren</translation>
    </message>
    <message>
        <source>Run time the other way</source>
        <translation>Die Zeit in die andere Richtung laufen lassen</translation>
    </message>
    <message>
        <source>Compute &amp;backend</source>
        <translation>Rechen-&amp;Backend</translation>
    </message>
    <message>
        <source>&amp;Automatic</source>
        <translation>&amp;Automatisch</translation>
    </message>
    <message>
        <source>The GPU for scenes large enough to gain from it, else the CPU</source>
        <translation>Die GPU für Szenen, die groß genug sind, um davon zu profitieren, sonst die CPU</translation>
    </message>
    <message>
        <source>&amp;CPU</source>
        <translation>&amp;CPU</translation>
    </message>
    <message>
        <source>The OpenMP reference models</source>
        <translation>Die OpenMP-Referenzmodelle</translation>
    </message>
    <message>
        <source>&amp;GPU (OpenGL compute)</source>
        <translation>&amp;GPU (OpenGL-Compute)</translation>
    </message>
    <message>
        <source>OpenGL 4.3 compute shaders; the CPU where none exist</source>
        <translation>OpenGL-4.3-Compute-Shader; die CPU, wo es keine gibt</translation>
    </message>
    <message>
        <source>Benchmark this &amp;machine…</source>
        <translation>Diesen &amp;Rechner vermessen…</translation>
    </message>
    <message>
        <source>Time the gas and the fluid at growing N on the CPU and the GPU</source>
        <translation>Gas und Flüssigkeit bei wachsendem N auf CPU und GPU messen</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>Zoom to &amp;fit</source>
        <translation>&amp;Einpassen</translation>
    </message>
    <message>
        <source>Show the whole scene (the wheel zooms, the middle button pans)</source>
        <translation>Die ganze Szene zeigen (das Mausrad zoomt, die mittlere Taste verschiebt)</translation>
    </message>
    <message>
        <source>&amp;Projector mode</source>
        <translation>&amp;Projektormodus</translation>
    </message>
    <message>
        <source>Large fonts and thick lines for a classroom projector</source>
        <translation>Große Schrift und dicke Linien für einen Projektor im Klassenraum</translation>
    </message>
    <message>
        <source>Experiment</source>
        <translation>Experiment</translation>
    </message>
    <message>
        <source> Scene </source>
        <translation> Szene </translation>
    </message>
    <message>
        <source>The kind of simulation: choosing one opens its first built-in experiment</source>
        <translation>Die Art der Simulation: Die Auswahl öffnet ihr erstes eingebautes Experiment</translation>
    </message>
    <message>
        <source> Preset </source>
        <translation> Vorlage </translation>
    </message>
    <message>
        <source>Built-in experiments and your saved presets</source>
        <translation>Eingebaute Experimente und Ihre gespeicherten Vorlagen</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Ziehen</translation>
    </message>
    <message>
        <source>Spawn</source>
        <translation>Erzeugen</translation>
    </message>
    <message>
        <source>Drag a rectangle to fill it with particles, or click for one</source>
        <translation>Ein Rechteck aufziehen, um es mit Teilchen zu füllen, oder für eines klicken</translation>
    </message>
    <message>
        <source>Add disc</source>
        <translation>Scheibe hinzufügen</translation>
    </message>
    <message>
        <source>Click to place a disc obstacle</source>
        <translation>Klicken, um ein scheibenförmiges Hindernis zu setzen</translation>
    </message>
    <message>
        <source>Add box</source>
        <translation>Kasten hinzufügen</translation>
    </message>
    <message>
        <source>Drag a rectangle to place a box obstacle</source>
        <translation>Ein Rechteck aufziehen, um ein kastenförmiges Hindernis zu setzen</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Click an obstacle to remove it</source>
        <translation>Ein Hindernis anklicken, um es zu entfernen</translation>
    </message>
    <message>
        <source>Piston</source>
        <translation>Kolben</translation>
    </message>
    <message>
        <source>Drag to move the piston (when enabled in Parameters)</source>
        <translation>Ziehen, um den Kolben zu bewegen (wenn in den Parametern eingeschaltet)</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <source>Switch gravity on or off</source>
        <translation>Schwerkraft ein- oder ausschalten</translation>
    </message>
    <message>
        <source> Cool </source>
        <translation> Kühlen </translation>
    </message>
    <message>
        <source> Heat </source>
        <translation> Heizen </translation>
    </message>
    <message>
        <source>Heat</source>
        <translation>Heizen</translation>
    </message>
    <message>
        <source>Raise the kinetic energy by 10 %</source>
        <translation>Die kinetische Energie um 10 % erhöhen</translation>
    </message>
    <message>
        <source>Cool</source>
        <translation>Kühlen</translation>
    </message>
    <message>
        <source>Lower the kinetic energy by 10 %</source>
        <translation>Die kinetische Energie um 10 % senken</translation>
    </message>
    <message>
        <source>%1 (mine)</source>
        <translation>%1 (eigene)</translation>
    </message>
    <message>
        <source>Pr&amp;eferences…</source>
        <translation>&amp;Einstellungen…</translation>
    </message>
    <message>
        <source>Choose the language of ParticleLab</source>
        <translation>Die Sprache von ParticleLab wählen</translation>
    </message>
    <message>
        <source>P&amp;resent</source>
        <translation>Prä&amp;sentation</translation>
    </message>
    <message>
        <source>Full screen: the viewport, one plot, big readouts and a lesson&apos;s controls (Escape leaves)</source>
        <translation>Vollbild: die Simulationsansicht, ein Diagramm, große Anzeigen und die Bedienelemente einer Unterrichtsstunde (Esc beendet)</translation>
    </message>
    <message>
        <source>This experiment has no piston: tick “Piston” in Parameters → Walls and fields.</source>
        <translation>Dieses Experiment hat keinen Kolben: „Kolben“ unter Parameter → Wände und Felder ankreuzen.</translation>
    </message>
    <message>
        <source>The piston moves while time runs (Space).</source>
        <translation>Der Kolben bewegt sich, während die Zeit läuft (Leertaste).</translation>
    </message>
    <message>
        <source>Compress</source>
        <translation>Verdichten</translation>
    </message>
    <message>
        <source>Move the piston left at the piston speed; again to hold it</source>
        <translation>Den Kolben mit der Kolbengeschwindigkeit nach links bewegen; erneut, um ihn anzuhalten</translation>
    </message>
    <message>
        <source>Expand</source>
        <translation>Entspannen</translation>
    </message>
    <message>
        <source>Move the piston right at the piston speed; again to hold it</source>
        <translation>Den Kolben mit der Kolbengeschwindigkeit nach rechts bewegen; erneut, um ihn anzuhalten</translation>
    </message>
    <message>
        <source>Experiments and snapshots (*.particlelab *.plsnap *.json)</source>
        <translation>Experimente und Momentaufnahmen (*.particlelab *.plsnap *.json)</translation>
    </message>
    <message>
        <source>Save sna&amp;pshot…</source>
        <translation>&amp;Momentaufnahme speichern…</translation>
    </message>
    <message>
        <source>Save the experiment with every particle, to continue exactly where it is</source>
        <translation>Das Experiment mit jedem Teilchen speichern, um genau an dieser Stelle weiterzumachen</translation>
    </message>
    <message>
        <source>Save snapshot</source>
        <translation>Momentaufnahme speichern</translation>
    </message>
    <message>
        <source>Snapshots (*.plsnap *.json)</source>
        <translation>Momentaufnahmen (*.plsnap *.json)</translation>
    </message>
    <message>
        <source>%1, read-only: %2 particles, %3 rows up to t = %4, step %5. Open a preset to simulate again.</source>
        <translation>%1, schreibgeschützt: %2 Teilchen, %3 Zeilen bis t = %4, Schritt %5. Zum erneuten Simulieren eine Vorlage öffnen.</translation>
    </message>
    <message>
        <source>Export to &amp;LAMMPS…</source>
        <translation>Nach LAMMPS e&amp;xportieren…</translation>
    </message>
    <message>
        <source>Write the gas in its current state as a LAMMPS deck into a folder</source>
        <translation>Das Gas im aktuellen Zustand als LAMMPS-Eingabe in einen Ordner schreiben</translation>
    </message>
    <message>
        <source>Export to LAMMPS: choose a folder</source>
        <translation>Nach LAMMPS exportieren: einen Ordner wählen</translation>
    </message>
    <message>
        <source>Cannot export to LAMMPS</source>
        <translation>Export nach LAMMPS nicht möglich</translation>
    </message>
    <message>
        <source>Open LAMMPS r&amp;un…</source>
        <translation>&amp;LAMMPS-Lauf öffnen…</translation>
    </message>
    <message>
        <source>Show a LAMMPS run of an exported deck (log.lammps and its dump) read-only</source>
        <translation>Einen LAMMPS-Lauf einer exportierten Eingabe (log.lammps und sein Dump) schreibgeschützt anzeigen</translation>
    </message>
    <message>
        <source>Open LAMMPS run: choose the deck&apos;s folder after LAMMPS ran in it</source>
        <translation>LAMMPS-Lauf öffnen: den Ordner der Eingabe wählen, nachdem LAMMPS darin gelaufen ist</translation>
    </message>
    <message>
        <source>Cannot open the LAMMPS run</source>
        <translation>Der LAMMPS-Lauf kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>No experiment is loaded.</source>
        <translation>Kein Experiment geladen.</translation>
    </message>
    <message>
        <source>Wrote the LAMMPS deck to %1; run it there with: %2</source>
        <translation>LAMMPS-Eingabe nach %1 geschrieben; dort ausführen mit: %2</translation>
    </message>
    <message>
        <source>LAMMPS run in %1</source>
        <translation>LAMMPS-Lauf in %1</translation>
    </message>
    <message>
        <source>LAMMPS run %1</source>
        <translation>LAMMPS-Lauf %1</translation>
    </message>
    <message>
        <source>Run on &amp;LAMMPS…</source>
        <translation>Mit &amp;LAMMPS rechnen…</translation>
    </message>
    <message>
        <source>Export the gas, run it with mpirun and LAMMPS, and open the run</source>
        <translation>Das Gas exportieren, mit mpirun und LAMMPS rechnen und den Lauf öffnen</translation>
    </message>
    <message>
        <source>Run on LAMMPS: choose a folder for the deck and LAMMPS&apos;s output</source>
        <translation>Mit LAMMPS rechnen: einen Ordner für die Eingabe und die Ausgabe von LAMMPS wählen</translation>
    </message>
    <message>
        <source>Run on LAMMPS</source>
        <translation>Mit LAMMPS rechnen</translation>
    </message>
    <message>
        <source>MPI ranks:</source>
        <translation>MPI-Prozesse:</translation>
    </message>
    <message>
        <source>Cannot run LAMMPS</source>
        <translation>LAMMPS kann nicht ausgeführt werden</translation>
    </message>
    <message>
        <source>The LAMMPS run did not open</source>
        <translation>Der LAMMPS-Lauf wurde nicht geöffnet</translation>
    </message>
    <message>
        <source>%1 is not installed: running on LAMMPS needs LAMMPS and MPI (Debian: apt install lammps openmpi-bin).</source>
        <translation>%1 ist nicht installiert: Rechnen mit LAMMPS braucht LAMMPS und MPI (Debian: apt install lammps openmpi-bin).</translation>
    </message>
    <message>
        <source>LAMMPS runs %1 steps on %2 ranks…</source>
        <translation>LAMMPS rechnet %1 Schritte auf %2 Prozessen…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>The LAMMPS run was cancelled; its deck and output so far are in %1.</source>
        <translation>Der LAMMPS-Lauf wurde abgebrochen; seine Eingabe und die bisherige Ausgabe liegen in %1.</translation>
    </message>
    <message>
        <source>LAMMPS failed (exit status %1) in %2; its last output:
%3</source>
        <translation>LAMMPS ist fehlgeschlagen (Exit-Status %1) in %2; seine letzte Ausgabe:
%3</translation>
    </message>
    <message>
        <source>Profile</source>
        <translation>Profil</translation>
    </message>
    <message>
        <source>Drag obstacles and the piston; drag empty space to pan (in the fluid: to pour; where fields are sampled: to read the local values)</source>
        <translation>Hindernisse und den Kolben ziehen; freie Fläche ziehen verschiebt die Ansicht (in der Flüssigkeit: gießt ein; wo Felder abgetastet werden: zeigt die örtlichen Werte)</translation>
    </message>
    <message>
        <source>Profile line</source>
        <translation>Profillinie</translation>
    </message>
    <message>
        <source>Drag a line across the flow: the Profile dock plots a sampled field along it</source>
        <translation>Ziehen Sie eine Linie quer durch die Strömung: das Dock „Profil“ zeigt ein abgetastetes Feld entlang der Linie</translation>
    </message>
    <message>
        <source>Expor&amp;t report…</source>
        <translation>Bericht expor&amp;tieren…</translation>
    </message>
    <message>
        <source>Write a lab report of the experiment: parameters, run, scene, plots, readouts</source>
        <translation>Einen Laborbericht des Experiments schreiben: Parameter, Lauf, Szene, Diagramme, Messwerte</translation>
    </message>
    <message>
        <source>Export report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <source>PDF (*.pdf);;Web page (*.html)</source>
        <translation>PDF (*.pdf);;Webseite (*.html)</translation>
    </message>
    <message>
        <source>Cannot write the report</source>
        <translation>Der Bericht kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>Record clip…</source>
        <translation>Clip aufnehmen…</translation>
    </message>
    <message>
        <source>Record a clip in simulated time (MP4, WebM or GIF); press again to stop</source>
        <translation>Einen Clip in simulierter Zeit aufnehmen (MP4, WebM oder GIF); erneut drücken zum Beenden</translation>
    </message>
    <message>
        <source>Record clip</source>
        <translation>Clip aufnehmen</translation>
    </message>
    <message>
        <source>MP4 video (*.mp4);;WebM video (*.webm);;GIF (*.gif)</source>
        <translation>MP4-Video (*.mp4);;WebM-Video (*.webm);;GIF (*.gif)</translation>
    </message>
    <message>
        <source>Cannot record</source>
        <translation>Aufnahme nicht möglich</translation>
    </message>
    <message>
        <source>Stop recording</source>
        <translation>Aufnahme beenden</translation>
    </message>
    <message>
        <source>● REC %1 s</source>
        <translation>● REC %1 s</translation>
    </message>
    <message>
        <source>%1 particles   t = %2   step %3   %4 steps/s (%5 %6 per second)   %7 fps   %8</source>
        <translation>%1 Teilchen   t = %2   Schritt %3   %4 Schritte/s (%5 %6 pro Sekunde)   %7 Bilder/s   %8</translation>
    </message>
    <message>
        <source>Automatic pace</source>
        <translation>Automatisches Tempo</translation>
    </message>
    <message>
        <source>As many steps as half of each frame allows, up to a pace that keeps the scene watchable</source>
        <translation>So viele Schritte, wie die Hälfte jedes Bildes erlaubt, bis zu einem Tempo, bei dem man der Szene noch folgen kann</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>Signed steps per frame: negative values run time backwards, 0 stands still ([ slower, ] faster); a number typed here fixes the pace</source>
        <translation>Schritte pro Bild mit Vorzeichen: negative Werte lassen die Zeit rückwärts laufen, 0 hält sie an ([ langsamer, ] schneller); eine hier eingegebene Zahl legt das Tempo fest</translation>
    </message>
    <message>
        <source>Hold to the right to heat, to the left to cool, the faster the further (at the right end kT doubles in about 4 s of the scene&apos;s pace); it springs back when released</source>
        <translation>Nach rechts halten zum Heizen, nach links zum Kühlen, je weiter, desto schneller (am rechten Ende verdoppelt sich kT in etwa 4 s im Tempo der Szene); losgelassen springt er zurück</translation>
    </message>
    <message>
        <source>auto </source>
        <translation>auto </translation>
    </message>
    <message>
        <source>Gravity %1</source>
        <translation>Schwerkraft %1</translation>
    </message>
    <message>
        <source>Gravity (g = %1 %2)</source>
        <translation>Schwerkraft (g = %1 %2)</translation>
    </message>
    <message>
        <source>This scene has no gravity (g = 0): set Gravity in Parameters</source>
        <translation>Diese Szene hat keine Schwerkraft (g = 0): Schwerkraft unter „Parameter“ einstellen</translation>
    </message>
    <message>
        <source>Switch gravity on or off (%1)</source>
        <translation>Schwerkraft ein- oder ausschalten (%1)</translation>
    </message>
    <message>
        <source>Gravity, heat and view</source>
        <translation>Schwerkraft, Heizen und Ansicht</translation>
    </message>
    <message>
        <source>&amp;Automatic colour scale</source>
        <translation>&amp;Automatische Farbskala</translation>
    </message>
    <message>
        <source>The top of the colour scale follows the particles as they heat up; off: the scene&apos;s fixed scale, so heating shows as redder colours</source>
        <translation>Das obere Ende der Farbskala folgt den Teilchen, wenn sie sich erwärmen; aus: die feste Skala der Szene, Erwärmen zeigt sich in röteren Farben</translation>
    </message>
    <message>
        <source>Encoding the last frames of the clip…</source>
        <translation>Die letzten Bilder des Clips werden kodiert…</translation>
    </message>
    <message>
        <source>%1 particles   t = %2   step %3   stopped   %4</source>
        <translation>%1 Teilchen   t = %2   Schritt %3   angehalten   %4</translation>
    </message>
</context>
<context>
    <name>pl::ui::MethodsLab</name>
    <message>
        <source>Time reversal</source>
        <translation>Zeitumkehr</translation>
    </message>
    <message>
        <source>Accuracy vs cost</source>
        <translation>Genauigkeit gegen Kosten</translation>
    </message>
    <message>
        <source>Stability map</source>
        <translation>Stabilitätskarte</translation>
    </message>
    <message>
        <source>Fluid</source>
        <translation>Flüssigkeit</translation>
    </message>
    <message>
        <source>DSMC</source>
        <translation>DSMC</translation>
    </message>
    <message>
        <source>MD vs DSMC</source>
        <translation>MD gegen DSMC</translation>
    </message>
</context>
<context>
    <name>pl::ui::PaceAdvice</name>
    <message>
        <source>%1 % of the watchable pace</source>
        <translation>%1 % des Tempos der Szene</translation>
    </message>
    <message>
        <source>This machine runs the scene at %1 % of the pace at which it is watchable: each step takes %2 ms for %3 particles. Fewer particles keep the pace.</source>
        <translation>Dieser Rechner führt die Szene mit %1 % des Tempos aus, bei dem man ihr noch folgen kann: Jeder Schritt dauert %2 ms für %3 Teilchen. Mit weniger Teilchen hält er das Tempo.</translation>
    </message>
    <message>
        <source>Use %1</source>
        <translation>%1 verwenden</translation>
    </message>
    <message>
        <source>A lighter experiment that this machine runs at the watchable pace; it restarts the experiment, and nothing changes until you press it.</source>
        <translation>Ein leichteres Experiment, das dieser Rechner im Tempo der Szene ausführt; es startet das Experiment neu, und nichts ändert sich, bevor Sie hier klicken.</translation>
    </message>
</context>
<context>
    <name>pl::ui::ParameterPanel</name>
    <message>
        <source>Reset now</source>
        <translation>Jetzt zurücksetzen</translation>
    </message>
    <message>
        <source>Restart the experiment so the parameters marked ⟲ take effect (Ctrl+R)</source>
        <translation>Das Experiment neu starten, damit die mit ⟲ markierten Parameter wirken (Strg+R)</translation>
    </message>
    <message>
        <source>Parameters marked ⟲ take effect on Reset; the others act at once.</source>
        <translation>Mit ⟲ markierte Parameter wirken nach „Zurücksetzen“, die anderen sofort.</translation>
    </message>
    <message numerus="yes">
        <source>%n change(s) wait for Reset.</source>
        <translation>
            <numerusform>%n Änderung wartet auf „Zurücksetzen“.</numerusform>
            <numerusform>%n Änderungen warten auf „Zurücksetzen“.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: “%2” is not a number (allowed: %3)</source>
        <translation>%1: „%2“ ist keine Zahl (erlaubt: %3)</translation>
    </message>
    <message>
        <source>Units: %1</source>
        <translation>Einheiten: %1</translation>
    </message>
    <message>
        <source>%1: “%2” is not a number: decimals are written with “%3” (allowed: %4)</source>
        <translation>%1: „%2“ ist keine Zahl: Dezimalstellen werden mit „%3“ abgetrennt (erlaubt: %4)</translation>
    </message>
</context>
<context>
    <name>pl::ui::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>The language of menus, panels and messages</source>
        <translation>Die Sprache von Menüs, Bedienfeldern und Meldungen</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
    <message>
        <source>A new language shows the next time ParticleLab starts.</source>
        <translation>Eine neue Sprache erscheint beim nächsten Start von ParticleLab.</translation>
    </message>
</context>
<context>
    <name>pl::ui::PresentMode</name>
    <message>
        <source>Present</source>
        <translation>Präsentation</translation>
    </message>
</context>
<context>
    <name>pl::ui::PresentPanel</name>
    <message>
        <source>Which of the scene&apos;s plots to show</source>
        <translation>Welches Diagramm der Szene gezeigt wird</translation>
    </message>
    <message>
        <source>Speed distribution</source>
        <translation>Geschwindigkeitsverteilung</translation>
    </message>
    <message>
        <source>v_x distribution</source>
        <translation>v_x-Verteilung</translation>
    </message>
    <message>
        <source>Leave (Esc)</source>
        <translation>Verlassen (Esc)</translation>
    </message>
</context>
<context>
    <name>pl::ui::ProfilePlot</name>
    <message>
        <source>The sampled field plotted along the profile line</source>
        <translation>Das abgetastete Feld, aufgetragen entlang der Profillinie</translation>
    </message>
    <message>
        <source>Field</source>
        <translation>Feld</translation>
    </message>
    <message>
        <source>distance along the line [m]</source>
        <translation>Abstand entlang der Linie [m]</translation>
    </message>
    <message>
        <source>Draw a line across the flow with the Profile line tool</source>
        <translation>Zeichnen Sie mit dem Werkzeug „Profillinie“ eine Linie quer durch die Strömung</translation>
    </message>
    <message>
        <source>This experiment samples no fields</source>
        <translation>Dieses Experiment tastet keine Felder ab</translation>
    </message>
    <message>
        <source>%1 along the line (%2 m)</source>
        <translation>%1 entlang der Linie (%2 m)</translation>
    </message>
</context>
<context>
    <name>pl::ui::RecommendBar</name>
    <message>
        <source>Largest %1 you accept</source>
        <translation>Größter akzeptierter Wert für %1</translation>
    </message>
    <message>
        <source>Recommend</source>
        <translation>Empfehlen</translation>
    </message>
    <message>
        <source>The cheapest measured setting whose %1 is at most the target</source>
        <translation>Die günstigste gemessene Einstellung, bei der %1 höchstens das Ziel erreicht</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <source>Target %1:</source>
        <translation>Ziel für %1:</translation>
    </message>
    <message>
        <source>Run the sweep first: there is nothing measured to choose from.</source>
        <translation>Zuerst die Parameterstudie ausführen: Es gibt noch keine Messwerte zur Auswahl.</translation>
    </message>
    <message>
        <source>No measured setting reaches %1; the best was not enough. Lower the target or extend the sweep.</source>
        <translation>Keine gemessene Einstellung erreicht %1; auch die beste reichte nicht. Das Ziel senken oder die Parameterstudie erweitern.</translation>
    </message>
    <message>
        <source>%1: error %2 at %3 %4</source>
        <translation>%1: Fehler %2 bei %3 %4</translation>
    </message>
    <message>
        <source>this sweep&apos;s settings belong to its test problem</source>
        <translation>die Einstellungen dieser Parameterstudie gehören zu ihrem Testproblem</translation>
    </message>
    <message>
        <source>Set this on the current experiment</source>
        <translation>Dies im aktuellen Experiment einstellen</translation>
    </message>
    <message>
        <source>Not applied: %1</source>
        <translation>Nicht übernommen: %1</translation>
    </message>
    <message>
        <source>Applied: %1</source>
        <translation>Übernommen: %1</translation>
    </message>
    <message>
        <source>s per unit time</source>
        <translation>s pro Zeiteinheit</translation>
    </message>
</context>
<context>
    <name>pl::ui::RecordDialog</name>
    <message>
        <source>Record clip</source>
        <translation>Clip aufnehmen</translation>
    </message>
    <message>
        <source>MP4 (H.264): plays everywhere</source>
        <translation>MP4 (H.264): läuft überall</translation>
    </message>
    <message>
        <source>WebM (VP9): smaller, for the web</source>
        <translation>WebM (VP9): kleiner, fürs Web</translation>
    </message>
    <message>
        <source>GIF: loops, for slides and chat</source>
        <translation>GIF: in Schleife, für Folien und Chats</translation>
    </message>
    <message>
        <source>The file&apos;s suffix decides in the end: a name ending in .webm is WebM</source>
        <translation>Am Ende entscheidet die Endung der Datei: ein Name auf .webm ergibt WebM</translation>
    </message>
    <message>
        <source>The scene alone</source>
        <translation>Nur die Szene</translation>
    </message>
    <message>
        <source>The scene beside %1</source>
        <translation>Die Szene neben %1</translation>
    </message>
    <message>
        <source>%1 × %2 (square)</source>
        <translation>%1 × %2 (quadratisch)</translation>
    </message>
    <message>
        <source>Custom size</source>
        <translation>Eigene Größe</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source> frames/s</source>
        <translation> Bilder/s</translation>
    </message>
    <message>
        <source>Every frame is the state after this many steps, so the clip shows simulated time evenly however long each step took</source>
        <translation>Jedes Bild ist der Zustand nach so vielen Schritten; so zeigt der Clip die simulierte Zeit gleichmäßig, wie lange jeder Schritt auch dauerte</translation>
    </message>
    <message>
        <source>Watchable pace</source>
        <translation>Tempo der Szene</translation>
    </message>
    <message>
        <source>The steps per frame that play the scene at the pace it is best watched at</source>
        <translation>Die Schritte pro Bild, mit denen die Szene in dem Tempo läuft, in dem man ihr am besten folgen kann</translation>
    </message>
    <message>
        <source>Title at the start and the time in the corner</source>
        <translation>Titel am Anfang und Zeit in der Ecke</translation>
    </message>
    <message>
        <source>Record…</source>
        <translation>Aufnehmen…</translation>
    </message>
    <message>
        <source>Format:</source>
        <translation>Format:</translation>
    </message>
    <message>
        <source>Shows:</source>
        <translation>Zeigt:</translation>
    </message>
    <message>
        <source>Size:</source>
        <translation>Größe:</translation>
    </message>
    <message>
        <source>Frame rate:</source>
        <translation>Bildrate:</translation>
    </message>
    <message>
        <source>Steps per frame:</source>
        <translation>Schritte pro Bild:</translation>
    </message>
    <message>
        <source>%1 %2 of simulated time per frame, %3 %2 per second of clip</source>
        <translation>%1 %2 simulierte Zeit pro Bild, %3 %2 pro Sekunde Clip</translation>
    </message>
    <message>
        <source>%1 cannot store an odd side (its colours are kept at half resolution): use an even width and height.</source>
        <translation>%1 kann keine ungerade Seitenlänge speichern (die Farben werden mit halber Auflösung gespeichert): bitte eine gerade Breite und Höhe wählen.</translation>
    </message>
</context>
<context>
    <name>pl::ui::RelaxPage</name>
    <message>
        <source>Two beams at ±u relax to one Maxwellian. Molecular dynamics resolves every contact of soft disks (about 30 steps each); DSMC with two velocity components only samples which pairs collide. Both reach the same Maxwellian in the same number of collisions: for a dilute gas&apos;s velocities DSMC is enough. It is not for a dense gas (collisions stop being binary and the finite size of the disks changes the pressure) or anything about structure (g(r), crystals, flow around an obstacle at the scale of a disk).</source>
        <translation>Zwei Strahlen mit ±u relaxieren zu einer Maxwell-Verteilung. Die Molekulardynamik löst jeden Kontakt weicher Scheiben auf (je etwa 30 Schritte); DSMC mit zwei Geschwindigkeitskomponenten zieht nur Stichproben, welche Paare stoßen. Beide erreichen dieselbe Maxwell-Verteilung nach derselben Zahl von Stößen: Für die Geschwindigkeiten eines verdünnten Gases genügt DSMC. Nicht aber für ein dichtes Gas (Stöße sind nicht mehr binär, und die endliche Größe der Scheiben ändert den Druck) oder für Fragen der Struktur (g(r), Kristalle, Umströmung eines Hindernisses auf der Größenskala einer Scheibe).</translation>
    </message>
    <message>
        <source>Particles:</source>
        <translation>Teilchen:</translation>
    </message>
    <message>
        <source>Collisions each:</source>
        <translation>Stöße je Teilchen:</translation>
    </message>
    <message>
        <source>collisions per particle</source>
        <translation>Stöße pro Teilchen</translation>
    </message>
    <message>
        <source>kurtosis of v_x (Maxwellian: 3)</source>
        <translation>Kurtosis von v_x (Maxwell-Verteilung: 3)</translation>
    </message>
    <message>
        <source>molecular dynamics</source>
        <translation>Molekulardynamik</translation>
    </message>
    <message>
        <source>DSMC (in the plane)</source>
        <translation>DSMC (in der Ebene)</translation>
    </message>
    <message>
        <source>Maxwellian</source>
        <translation>Maxwell-Verteilung</translation>
    </message>
    <message>
        <source>MD: %1 s for %2 particle-steps</source>
        <translation>MD: %1 s für %2 Teilchenschritte</translation>
    </message>
    <message>
        <source>Both relaxed: %1 and %2 collisions per particle</source>
        <translation>Beide relaxiert: %1 und %2 Stöße pro Teilchen</translation>
    </message>
    <message>
        <source>MD took %1 s, DSMC %2 s: DSMC was %3× cheaper for the same relaxation. Final v_x distributions: KS distance %4, p = %5 (%6).</source>
        <translation>MD brauchte %1 s, DSMC %2 s: DSMC war für dieselbe Relaxation %3× günstiger. Endgültige v_x-Verteilungen: KS-Abstand %4, p = %5 (%6).</translation>
    </message>
    <message>
        <source>one Maxwellian</source>
        <translation>eine Maxwell-Verteilung</translation>
    </message>
    <message>
        <source>they differ</source>
        <translation>sie unterscheiden sich</translation>
    </message>
    <message>
        <source>MD against DSMC</source>
        <translation>MD gegen DSMC</translation>
    </message>
</context>
<context>
    <name>pl::ui::SeriesPlot</name>
    <message>
        <source>time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>%1 (backwards)</source>
        <translation>%1 (rückwärts)</translation>
    </message>
    <message>
        <source>time running backwards</source>
        <translation>Zeit läuft rückwärts</translation>
    </message>
    <message>
        <source>time run, Σ |Δt|</source>
        <translation>gelaufene Zeit, Σ |Δt|</translation>
    </message>
</context>
<context>
    <name>pl::ui::SimulationController</name>
    <message>
        <source>%1 would make every step unstable: %2</source>
        <translation>%1 machte jeden Schritt instabil: %2</translation>
    </message>
    <message>
        <source>%1 (to %2)</source>
        <translation>%1 (auf %2)</translation>
    </message>
    <message>
        <source>The last change before it: %1. Set it back, or press Reset (Ctrl+R).

%2</source>
        <translation>Die letzte Änderung davor: %1. Nehmen Sie sie zurück oder drücken Sie „Zurücksetzen“ (Strg+R).

%2</translation>
    </message>
    <message numerus="yes">
        <source>%n particle(s) had no room beside the new body and were removed.</source>
        <translation>
            <numerusform>%n Teilchen hatte neben dem neuen Körper keinen Platz und wurde entfernt.</numerusform>
            <numerusform>%n Teilchen hatten neben dem neuen Körper keinen Platz und wurden entfernt.</numerusform>
        </translation>
    </message>
    <message>
        <source>Computing on the %1 now; the experiment restarted from its parameters.</source>
        <translation>Rechnet jetzt auf der %1; das Experiment wurde mit seinen Parametern neu gestartet.</translation>
    </message>
    <message>
        <source>GPU</source>
        <translation>GPU</translation>
    </message>
    <message>
        <source>CPU</source>
        <translation>CPU</translation>
    </message>
    <message>
        <source>No experiment is loaded.</source>
        <translation>Kein Experiment geladen.</translation>
    </message>
    <message>
        <source>The run is complete (%1 steps): Reset to run it again, or raise the run length.</source>
        <translation>Der Lauf ist beendet (%1 Schritte): Zurücksetzen, um ihn erneut auszuführen, oder die Laufdauer erhöhen.</translation>
    </message>
    <message>
        <source>This scene cannot run backwards: its collisions are random, so time has one direction.</source>
        <translation>Diese Szene kann nicht rückwärts laufen: Ihre Stöße sind zufällig, daher hat die Zeit eine Richtung.</translation>
    </message>
    <message>
        <source>Run complete: %1 steps.</source>
        <translation>Lauf beendet: %1 Schritte.</translation>
    </message>
    <message>
        <source>This run is read-only: open a preset to change parameters.</source>
        <translation>Dieser Lauf ist schreibgeschützt: Zum Ändern der Parameter eine Vorlage öffnen.</translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <source>Cannot reset: %1</source>
        <translation>Zurücksetzen nicht möglich: %1</translation>
    </message>
</context>
<context>
    <name>pl::ui::StabilityPage</name>
    <message>
        <source>Where each integrator fails. A light disk caged between two heavy ones oscillates at ω = √(2k) (the contact of two unit-mass disks) for 2000 steps: stable, inaccurate (energy error above 1 %) or unstable (its energy grew 50×). The line is the linear theory&apos;s limit: ω dt = 2 for Verlet and symplectic Euler, 2√2 for RK4, 1.57 for Forest–Ruth; explicit Euler has none.</source>
        <translation>Wo jeder Integrator versagt. Eine leichte Scheibe, eingesperrt zwischen zwei schweren, schwingt 2000 Schritte lang mit ω = √(2k) (der Kontakt zweier Scheiben mit Einheitsmasse): stabil, ungenau (Energiefehler über 1 %) oder instabil (ihre Energie wuchs auf das 50-Fache). Die Linie ist die Grenze der linearen Theorie: ω dt = 2 für Verlet und symplektischen Euler, 2√2 für RK4, 1.57 für Forest–Ruth; der explizite Euler hat keine.</translation>
    </message>
    <message>
        <source>Integrator:</source>
        <translation>Integrator:</translation>
    </message>
    <message>
        <source>time step dt [T]</source>
        <translation>Zeitschritt dt [T]</translation>
    </message>
    <message>
        <source>stiffness k [M/T²] (unit masses)</source>
        <translation>Steifigkeit k [M/T²] (Einheitsmassen)</translation>
    </message>
    <message>
        <source>linear limit ω dt = %1</source>
        <translation>lineare Grenze ω dt = %1</translation>
    </message>
    <message>
        <source>current gas</source>
        <translation>aktuelles Gas</translation>
    </message>
    <message>
        <source>k = %1: no cell blew up</source>
        <translation>k = %1: keine Zelle ist explodiert</translation>
    </message>
    <message>
        <source>k = %1: stable up to ω dt = %2</source>
        <translation>k = %1: stabil bis ω dt = %2</translation>
    </message>
    <message>
        <source>Stability map</source>
        <translation>Stabilitätskarte</translation>
    </message>
</context>
<context>
    <name>pl::ui::ViewChooser</name>
    <message>
        <source>Particles</source>
        <translation>Teilchen</translation>
    </message>
    <message>
        <source>Number density</source>
        <translation>Teilchendichte</translation>
    </message>
    <message>
        <source>Flow speed</source>
        <translation>Strömungsgeschwindigkeit</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <source>Mach number</source>
        <translation>Machzahl</translation>
    </message>
    <message>
        <source>Colour &amp;map</source>
        <translation>&amp;Farbkarte</translation>
    </message>
    <message>
        <source>Show the particles or a sampled field as a colour map</source>
        <translation>Zeigt die Teilchen oder ein abgetastetes Feld als Farbkarte</translation>
    </message>
    <message>
        <source>Show the particles or a sampled field as a colour map (click the flow to read the local values)</source>
        <translation>Zeigt die Teilchen oder ein abgetastetes Feld als Farbkarte (ein Klick in die Strömung zeigt die örtlichen Werte)</translation>
    </message>
    <message>
        <source> Show </source>
        <translation> Anzeige </translation>
    </message>
</context>
<context>
    <name>pl::ui::ViewportCore</name>
    <message>
        <source>This experiment has no piston: tick “Piston” in Parameters → Walls and fields.</source>
        <translation>Dieses Experiment hat keinen Kolben: „Kolben“ unter Parameter → Wände und Felder ankreuzen.</translation>
    </message>
    <message>
        <source>This experiment samples no fields to draw a profile of.</source>
        <translation>Dieses Experiment tastet keine Felder ab, deren Profil sich zeichnen ließe.</translation>
    </message>
    <message>
        <source>Drag across the flow to draw the profile line.</source>
        <translation>Ziehen Sie quer durch die Strömung, um die Profillinie zu zeichnen.</translation>
    </message>
    <message>
        <source>At x = %1 m, y = %2 m</source>
        <translation>Bei x = %1 m, y = %2 m</translation>
    </message>
    <message>
        <source>Outside the sampled domain</source>
        <translation>Außerhalb des abgetasteten Gebiets</translation>
    </message>
    <message>
        <source>Averaged over the last %1 steps</source>
        <translation>Gemittelt über die letzten %1 Schritte</translation>
    </message>
    <message>
        <source>Not sampled yet: sampling starts after the start-up steps</source>
        <translation>Noch nicht abgetastet: die Mittelung beginnt nach den Anlaufschritten</translation>
    </message>
    <message>
        <source>The simulation stopped: its state is no longer physical. Press Reset (Ctrl+R) to start again; its message said which change to take back.</source>
        <translation>Die Simulation ist angehalten: ihr Zustand ist nicht mehr physikalisch. „Zurücksetzen“ (Strg+R) startet neu; ihre Meldung nannte die Änderung, die zurückzunehmen ist.</translation>
    </message>
    <message>
        <source>Scene: none loaded</source>
        <translation>Szene: keine geladen</translation>
    </message>
</context>
</TS>
