#include "scene/factory_table.h"

#include "core/error.h"

namespace bz::scene {

void FactoryTable::add(std::string kind, Factory factory) {
    factories_.insert_or_assign(std::move(kind), std::move(factory));
}

bool FactoryTable::contains(std::string_view kind) const {
    return factories_.find(kind) != factories_.end();
}

Entity FactoryTable::create(const Placement& placement) const {
    const auto it = factories_.find(placement.kind);
    if (it == factories_.end()) {
        std::string known;
        for (const auto& [name, factory] : factories_) {
            if (!known.empty()) known += ", ";
            known += name;
        }
        throw UserError("unknown object kind '" + placement.kind + "' (known kinds: " + known +
                        ")");
    }
    return it->second(placement);
}

std::vector<std::string> FactoryTable::kinds() const {
    std::vector<std::string> out;
    out.reserve(factories_.size());
    for (const auto& [name, factory] : factories_) out.push_back(name);
    return out;
}

}  // namespace bz::scene
