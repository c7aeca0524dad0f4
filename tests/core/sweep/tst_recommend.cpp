// Recommend picks the cheapest measured setting that meets the target, and never a failed one.
#include "common/sweep/Recommend.h"

#include <QtTest>

using namespace pl;
using namespace pl::methods;

class TestRecommend : public QObject {
    Q_OBJECT
private slots:
    void picksTheCheapestThatMeetsTheTarget() {
        const std::vector<Candidate> c{{"a", {{"dt", 1e-3}}, 1e-2, 1.0},
                                       {"b", {{"dt", 5e-4}}, 1e-4, 2.0},
                                       {"c", {{"dt", 2e-4}}, 1e-6, 5.0},
                                       {"blown", {{"dt", 1e-2}}, std::nan(""), 0.1},
                                       {"untimed", {{"dt", 1e-2}}, 1e-9, std::nan("")}};
        QCOMPARE(cheapestWithin(c, 1e-1)->label, std::string("a"));
        QCOMPARE(cheapestWithin(c, 1e-3)->label, std::string("b"));
        QCOMPARE(cheapestWithin(c, 1e-5)->label, std::string("c"));
        QCOMPARE(std::get<double>(cheapestWithin(c, 1e-5)->setting.at("dt")), 2e-4);
        QVERIFY(!cheapestWithin(c, 1e-7).has_value());
        QVERIFY(!cheapestWithin({}, 1.0).has_value());
    }
};

QTEST_GUILESS_MAIN(TestRecommend)
#include "tst_recommend.moc"
