<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>FieldOverlay</name>
    <message numerus="yes">
        <source>mean of the last %n step(s)</source>
        <translation>
            <numerusform>mean of the last %n step</numerusform>
            <numerusform>mean of the last %n steps</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>mean of %n step(s)</source>
        <translation>
            <numerusform>mean of %n step</numerusform>
            <numerusform>mean of %n steps</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SceneDescription</name>
    <message numerus="yes">
        <source>%n particle(s).</source>
        <translation>
            <numerusform>%n particle.</numerusform>
            <numerusform>%n particles.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n obstacle(s).</source>
        <translation>
            <numerusform>%n obstacle.</numerusform>
            <numerusform>%n obstacles.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pl::ui::DistributionPlot</name>
    <message numerus="yes">
        <source>%n sample(s)</source>
        <comment>a spin box&apos;s value and unit</comment>
        <translation>
            <numerusform>%n sample</numerusform>
            <numerusform>%n samples</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pl::ui::ParameterPanel</name>
    <message numerus="yes">
        <source>%n change(s) wait for Reset.</source>
        <translation>
            <numerusform>%n change waits for Reset.</numerusform>
            <numerusform>%n changes wait for Reset.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pl::ui::SimulationController</name>
    <message numerus="yes">
        <source>%n particle(s) had no room beside the new body and were removed.</source>
        <translation>
            <numerusform>%n particle had no room beside the new body and was removed.</numerusform>
            <numerusform>%n particles had no room beside the new body and were removed.</numerusform>
        </translation>
    </message>
</context>
</TS>
