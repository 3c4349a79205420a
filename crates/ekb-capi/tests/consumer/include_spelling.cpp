// The drop-in under one of its include spellings (EKB_SPELLING 1 to 6): the plain one, the
// document's (utilities/) and the robot's node's (behaviorController/), each with "" and <>.
#if EKB_SPELLING == 1
#include "environmentKnowledgeBaseInterface.h"
#elif EKB_SPELLING == 2
#include <environmentKnowledgeBaseInterface.h>
#elif EKB_SPELLING == 3
#include "utilities/environmentKnowledgeBaseInterface.h"
#elif EKB_SPELLING == 4
#include <utilities/environmentKnowledgeBaseInterface.h>
#elif EKB_SPELLING == 5
#include "behaviorController/environmentKnowledgeBaseInterface.h"
#elif EKB_SPELLING == 6
#include <behaviorController/environmentKnowledgeBaseInterface.h>
#else
#error "EKB_SPELLING is 1 to 6"
#endif

int main() {
    Environment::TourSpecificationType tour;
    return sizeof tour.locationIdNumber / sizeof tour.locationIdNumber[0] == MAX_NUMBER_OF_TOUR_LOCATIONS ? 0 : 1;
}
