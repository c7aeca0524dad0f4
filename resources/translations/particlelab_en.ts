<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
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
</TS>
