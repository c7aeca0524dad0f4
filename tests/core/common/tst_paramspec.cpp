// ParamSpec: every kind of bad value is rejected with a message naming the key and the allowed range.
#include "common/ParamSpec.h"

#include <QtTest>
#include <limits>

using namespace pl;

namespace {
ParamSpec realSpec() {
    ParamSpec s = makeSpec("dt", "Time step", "T", "Integration", "A signed time step.", -1, 1, 0, 0.5);
    s.nonZero = true;
    return s;
}

struct Sample {
    double speed = 1.0;
    long long count = 4;
    std::string mode = "a";
};

std::vector<ParamField<Sample>> sampleFields() {
    ParamSpec speed;
    speed.key = "speed";
    speed.min = 0;
    speed.max = 10;
    ParamSpec count;
    count.key = "count";
    count.min = 0;
    count.max = 100;
    ParamSpec mode;
    mode.key = "mode";
    mode.kind = ParamKind::Choice;
    mode.choices = {"a", "b"};
    return {bindReal(&Sample::speed, speed), bindInteger(&Sample::count, count),
            bindText(&Sample::mode, mode)};
}
enum class Shade { Light, Dark };
const ChoiceTable<Shade>& choiceTable(Shade) {
    static const ChoiceTable<Shade> table{{Shade::Light, "light"}, {Shade::Dark, "dark"}};
    return table;
}

struct Painted {
    Shade shade = Shade::Dark; // not the table's first entry: the default comes from the struct
};
} // namespace

class TestParamSpec : public QObject {
    Q_OBJECT
private slots:
    void acceptsValuesInRange() {
        QVERIFY(checkValue(realSpec(), 0.5).empty());
        QVERIFY(checkValue(realSpec(), -1.0).empty());
    }
    void rejectsOutOfRangeNamingKeyAndRange() {
        const std::string m = checkValue(realSpec(), 2.0);
        QVERIFY(m.find("'dt'") != std::string::npos);
        QVERIFY(m.find("[-1, 1]") != std::string::npos);
    }
    void rejectsNonFinite() {
        QVERIFY(checkValue(realSpec(), std::numeric_limits<double>::quiet_NaN()).find("finite") !=
                std::string::npos);
        QVERIFY(checkValue(realSpec(), std::numeric_limits<double>::infinity()).find("finite") !=
                std::string::npos);
        // "nan" typed on the command line parses, then fails the check.
        QVERIFY(!checkValue(realSpec(), parseValue(realSpec(), "nan")).empty());
    }
    void rejectsZeroWhenNonZero() {
        QVERIFY(checkValue(realSpec(), 0.0).find("must not be 0") != std::string::npos);
    }
    void rejectsWrongType() {
        QVERIFY(checkValue(realSpec(), std::string("fast")).find("must be a number") != std::string::npos);
        QVERIFY_THROWS_EXCEPTION(ParamError, parseValue(realSpec(), "0.1x"));
    }
    void integersMustBeWhole() {
        ParamSpec s = realSpec();
        s.kind = ParamKind::Integer;
        s.nonZero = false;
        QVERIFY(checkValue(s, 0.5).find("integer") != std::string::npos);
    }
    void choicesListTheOptions() {
        ParamSpec s;
        s.key = "integrator";
        s.kind = ParamKind::Choice;
        s.choices = {"velocity-verlet", "rk4"};
        const auto m = checkValue(s, std::string("leapfrog"));
        QVERIFY(m.find("velocity-verlet, rk4") != std::string::npos);
    }
    void booleansParseCommonSpellings() {
        ParamSpec s;
        s.key = "piston_enabled";
        s.kind = ParamKind::Boolean;
        QCOMPARE(std::get<bool>(parseValue(s, "on")), true);
        QCOMPARE(std::get<bool>(parseValue(s, "false")), false);
        QVERIFY_THROWS_EXCEPTION(ParamError, parseValue(s, "maybe"));
    }
    void withValuesAppliesAllOrNothing() {
        const auto fields = sampleFields();
        const Sample base;
        const Sample changed = withValues(base, fields, {{"speed", 2.0}, {"mode", std::string("b")}});
        QCOMPARE(changed.speed, 2.0);
        QCOMPARE(changed.mode, std::string("b"));
        try {
            (void)withValues(base, fields, {{"count", 5.0}, {"speed", 50.0}});
            QFAIL("out-of-range value accepted");
        } catch (const ParamError& e) {
            QCOMPARE(e.key(), std::string("speed"));
        }
        QVERIFY_THROWS_EXCEPTION(ParamError, (void)withValues(base, fields, {{"colour", 1.0}}));
    }
    void choicesBindToEnums() {
        const std::vector<ParamField<Painted>> fields{
            bindChoice(&Painted::shade, makeChoice("shade", "Shade", "Look", "Light or dark."))};
        const ParamSpec& spec = fields[0].spec;
        QCOMPARE(spec.kind, ParamKind::Choice);
        QCOMPARE(spec.choices, (std::vector<std::string>{"light", "dark"}));
        QCOMPARE(std::get<std::string>(spec.defaultValue), std::string("dark"));
        QCOMPARE(std::get<std::string>(valuesOf(Painted{}, fields).at("shade")), std::string("dark"));
        const Painted light = withValues(Painted{}, fields, {{"shade", std::string("light")}});
        QVERIFY(light.shade == Shade::Light);
        QCOMPARE(nameOf(light.shade), std::string("light"));
        QVERIFY(choiceNamed<Shade>("dark") == Shade::Dark);
        QVERIFY(!choiceNamed<Shade>("drak"));
        try {
            (void)withValues(Painted{}, fields, {{"shade", std::string("drak")}});
            QFAIL("a misspelt choice was accepted");
        } catch (const ParamError& e) {
            QVERIFY2(std::string(e.what()).find("light, dark") != std::string::npos, e.what());
        }
    }
    void errorsNameParametersByKeyOrByLabel() {
        // The command line reads keys as it always did; the panel reads each parameter's label.
        const ParamError e("count_a", "{count_a} + {count_b} = 9 exceeds '{max_particles}' = 8 {not a key}");
        QCOMPARE(std::string(e.what()),
                 std::string("count_a + count_b = 9 exceeds 'max_particles' = 8 {not a key}"));
        const auto label = [](const std::string& key) {
            return key == "count_a" ? "Disks (A)" : "[" + key + "]";
        };
        QCOMPARE(nameParameters(e.message(), label),
                 std::string("Disks (A) + [count_b] = 9 exceeds [max_particles] = 8 {not a key}"));
        try {
            (void)withValues(Sample{}, sampleFields(), {{"speed", 50.0}});
            QFAIL("out-of-range value accepted");
        } catch (const ParamError& e) {
            QCOMPARE(nameParameters(e.message(), label).rfind("[speed] is out of range: 50", 0),
                     std::size_t(0));
        }
    }
    void smallNumbersKeepTheirDigits() {
        QCOMPARE(formatNumber(0.00012345, 3), std::string("0.000123"));
        QCOMPARE(formatNumber(1.5e-9, 2), std::string("1.5e-09"));
        QCOMPARE(formatNumber(2500, 6), std::string("2500"));
    }
};

QTEST_APPLESS_MAIN(TestParamSpec)
#include "tst_paramspec.moc"
