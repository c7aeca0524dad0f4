// Cell list: the counting sort groups every point by cell, and the 3×3 block around a point's cell
// holds every neighbour within the cell size (checked against brute force).
#include "common/CellList.h"
#include "common/Philox.h"

#include <QtTest>
#include <set>

using namespace pl;

class TestCellList : public QObject {
    Q_OBJECT
private slots:
    void countingSortIsAPermutationGroupedByCell() {
        CellList cells;
        cells.configure(-1, -1, 1, 1, 0.1);
        QCOMPARE(cells.cellsX(), 20);
        std::vector<double> x, y;
        for (std::uint32_t i = 0; i < 5000; ++i) {
            const auto [u, v] = uniformPair(randomWords(5, RngPurpose::InitialPosition, i, 0));
            x.push_back(-1 + 2 * u);
            y.push_back(-1 + 2 * v);
        }
        cells.build(x.data(), y.data(), x.size());
        const auto& order = cells.order();
        const auto& start = cells.cellStart();
        QCOMPARE(start.back(), 5000u);
        std::vector<bool> seen(x.size(), false);
        for (std::size_t c = 0; c + 1 < start.size(); ++c) {
            for (auto k = start[c]; k < start[c + 1]; ++k) {
                QCOMPARE(static_cast<std::size_t>(cells.cellOf(x[order[k]], y[order[k]])), c);
                QVERIFY(!seen[order[k]]);
                seen[order[k]] = true;
                if (k > start[c]) QVERIFY(order[k] > order[k - 1]); // stable: deterministic
            }
        }
    }

    void neighbourBlockFindsEveryCloseePair() {
        const double range = 0.07;
        CellList cells;
        cells.configure(0, 0, 1, 0.6, range);
        std::vector<double> x, y;
        for (std::uint32_t i = 0; i < 1500; ++i) {
            const auto [u, v] = uniformPair(randomWords(8, RngPurpose::InitialPosition, i, 0));
            // A few points slightly outside the box: clamped into edge cells, still found.
            x.push_back(-0.02 + 1.04 * u);
            y.push_back(-0.02 + 0.64 * v);
        }
        cells.build(x.data(), y.data(), x.size());
        std::set<std::pair<std::uint32_t, std::uint32_t>> brute, found;
        for (std::uint32_t i = 0; i < x.size(); ++i)
            for (std::uint32_t j = 0; j < x.size(); ++j)
                if (i != j && std::hypot(x[i] - x[j], y[i] - y[j]) < range) brute.insert({i, j});
        const int nx = cells.cellsX(), ny = cells.cellsY();
        for (std::uint32_t i = 0; i < x.size(); ++i) {
            const int cx = cells.cellX(x[i]), cy = cells.cellY(y[i]);
            for (int gy = std::max(cy - 1, 0); gy <= std::min(cy + 1, ny - 1); ++gy)
                for (int gx = std::max(cx - 1, 0); gx <= std::min(cx + 1, nx - 1); ++gx) {
                    const int c = gy * nx + gx;
                    for (auto k = cells.cellStart()[c]; k < cells.cellStart()[c + 1]; ++k) {
                        const auto j = cells.order()[k];
                        if (j != i && std::hypot(x[i] - x[j], y[i] - y[j]) < range) found.insert({i, j});
                    }
                }
        }
        QVERIFY(brute.size() > 1000);
        QVERIFY(found == brute);
    }

    void gridStaysBoundedForTinyCells() {
        CellList cells;
        cells.configure(0, 0, 1000, 1000, 1e-6);
        QVERIFY(double(cells.cellsX()) * cells.cellsY() <= double(1 << 26));
        QVERIFY(cells.cellSize() >= 1e-6);
    }

    void nanGoesToCellZero() {
        CellList cells;
        cells.configure(0, 0, 1, 1, 0.25);
        QCOMPARE(cells.cellOf(std::nan(""), 0.9), 12);
    }
};

QTEST_APPLESS_MAIN(TestCellList)
#include "tst_celllist.moc"
