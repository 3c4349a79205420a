// A program that catches around the drop-in's constructor gets control, with every finding
// in the exception, and the constructor has logged nothing (run_drop_in.cmake checks that
// standard error is empty). Then the program ends normally, and nothing else is caught:
// the drop-in's terminate handler passes other exceptions on.
#include <exception>
#include <stdexcept>

#include "environmentKnowledgeBaseInterface.h"

int main(int argc, char **) {
    try {
        Environment::EnvironmentKnowledgeBase knowledgeBase;
        printf("loaded\n");
        return 2;
    } catch (const std::exception &error) {
        const ekb::LoadError *refused = dynamic_cast<const ekb::LoadError *>(&error);
        if (refused == nullptr) return 3;
        std::size_t errors = 0;
        for (const ekb::Finding &finding : refused->findings()) errors += finding.severity == ekb::Severity::error;
        printf("caught: %zu findings, %zu errors: %s\n", refused->findings().size(), errors, error.what());
    }
    // With an argument: an exception other than ekb::LoadError escapes, and ends the program
    // as it would without ekb (the previous terminate handler: abort).
    if (argc > 1) throw std::logic_error("not ekb's");
    return 0;
}
