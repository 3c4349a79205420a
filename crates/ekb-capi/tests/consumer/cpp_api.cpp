// ekb::KnowledgeBase: the tour of the file named on the command line, or its findings.
#include <iostream>

#include "ekb.hpp"

int main(int argc, char **argv) {
    if (argc != 2) return 2;
    try {
        ekb::KnowledgeBase kb = ekb::KnowledgeBase::open(argv[1]);
        for (std::uint32_t id : kb.tour())
            std::cout << id << ' ' << kb.location(id)->description.value_or("") << '\n';
    } catch (const ekb::LoadError &error) {
        for (const ekb::Finding &finding : error.findings())
            if (finding.severity == ekb::Severity::error) std::cout << finding.toString() << '\n';
        return 1;
    }
    return 0;
}
