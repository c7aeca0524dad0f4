// GasState storage management.
#include "GasState.h"

namespace pl {

void GasState::resize(std::size_t n) {
    for (auto* v : {&x, &y, &vx, &vy, &ax, &ay, &potential, &virial, &wallImpulse}) v->resize(n, 0.0);
    species.resize(n, 0);
    id.resize(n, 0);
    contactsBegun.resize(n, 0);
}

namespace {
template <class T> void reorder(std::vector<T>& values, const std::vector<std::uint32_t>& newToOld) {
    std::vector<T> out(values.size());
    for (std::size_t n = 0; n < out.size(); ++n) out[n] = values[newToOld[n]];
    values.swap(out);
}
} // namespace

void GasState::permute(const std::vector<std::uint32_t>& newToOld) {
    for (auto* v : {&x, &y, &vx, &vy, &ax, &ay, &potential, &virial, &wallImpulse}) reorder(*v, newToOld);
    reorder(species, newToOld);
    reorder(id, newToOld);
    reorder(contactsBegun, newToOld);
}

void GasState::append(double px, double py, double pvx, double pvy, std::uint8_t s, std::uint32_t pid) {
    const std::size_t i = size();
    resize(i + 1);
    x[i] = px, y[i] = py, vx[i] = pvx, vy[i] = pvy, species[i] = s, id[i] = pid;
}

} // namespace pl
