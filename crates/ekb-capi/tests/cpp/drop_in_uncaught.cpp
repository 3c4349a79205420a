// A program written for the document's class, as the robot's node is: the knowledge base a
// global object, constructed before main, nothing caught. On a refused file it must end with
// the findings, errors first, one fatal line, and exit status 1: not terminate and SIGABRT.
// (run_drop_in.cmake runs it.)
#include "environmentKnowledgeBaseInterface.h"

EnvironmentKnowledgeBase knowledgeBase;

int main() {
    TourSpecificationType tour;
    if (!knowledgeBase.getTour(&tour)) return 3;
    printf("main: %d stops\n", tour.numberOfLocations);
    return 0;
}
