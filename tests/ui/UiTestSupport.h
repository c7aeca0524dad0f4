// Helpers for widget tests: answer modal message boxes automatically and count them.
#pragma once

#include <QApplication>
#include <QMessageBox>
#include <QTimer>

namespace pl::test {

// While alive, accepts every QMessageBox that opens and remembers its text.
class MessageBoxAnswerer : public QObject {
public:
    explicit MessageBoxAnswerer(QMessageBox::StandardButton answer = QMessageBox::Ok) : answer_(answer) {
        timer_.setInterval(20);
        connect(&timer_, &QTimer::timeout, this, [this] {
            for (QWidget* w : QApplication::topLevelWidgets()) {
                auto* box = qobject_cast<QMessageBox*>(w);
                if (!box || !box->isVisible()) continue;
                texts.append(box->text());
                QAbstractButton* button = box->button(answer_);
                if (button)
                    button->click();
                else
                    box->accept();
            }
        });
        timer_.start();
    }
    QStringList texts;

private:
    QMessageBox::StandardButton answer_;
    QTimer timer_;
};

} // namespace pl::test
