#include "GLViewport.h"

#include "SimulationController.h"
#include "ViewportCore.h"
#include "ViewportWindow.h"

#include <QVBoxLayout>

namespace pl::ui {

GLViewport::GLViewport(SimulationController* controller, QWidget* parent)
    : QWidget(parent), core_(new ViewportCore(controller, this)), window_(new ViewportWindow(core_)),
      container_(createWindowContainer(window_, this)) {
    setFocusPolicy(Qt::StrongFocus); // the window's keys start here, and a click brings them back
    // The native window covers this widget: it paints nothing of its own.
    setAttribute(Qt::WA_OpaquePaintEvent);
    setAttribute(Qt::WA_NoSystemBackground);
    // Input passes through the window and the container to this widget, where ViewportCore's event
    // filter and the window's shortcuts see it; focus stays here.
    container_->setAttribute(Qt::WA_TransparentForMouseEvents);
    container_->setFocusPolicy(Qt::NoFocus);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(container_);
    core_->setFrameRequest([this] { window_->update(); });
    connect(controller, &SimulationController::frameAdvanced, window_, &ViewportWindow::frameAdvanced);
    connect(controller, &SimulationController::modelReplaced, window_,
            qOverload<>(&QPaintDeviceWindow::update));
}

GLViewport::~GLViewport() {
    delete container_; // the window, whose GL clean-up reaches into core_, before core_ goes
}

long long GLViewport::framesFromGpuBuffers() const {
    return window_->framesFromGpuBuffers();
}

QImage GLViewport::grabFramebuffer() {
    return window_->renderImage();
}

} // namespace pl::ui
