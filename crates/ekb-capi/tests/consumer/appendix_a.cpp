// A program written for the document's EnvironmentKnowledgeBase class (D5.4.2 appendix A),
// nothing of ekb in it: it prints the tour, then every location.
#include "environmentKnowledgeBaseInterface.h"

int main() {
    EnvironmentKnowledgeBase knowledgeBase;
    TourSpecificationType tour;
    KeyValueType keyValue;

    if (!knowledgeBase.getTour(&tour)) {
        printf("no tour\n");
        return 1;
    }
    printf("%d stops:", tour.numberOfLocations);
    for (int i = 0; i < tour.numberOfLocations; i++) printf(" %d", tour.locationIdNumber[i]);
    printf("\n");
    for (int i = 0; i < tour.numberOfLocations; i++) {
        if (knowledgeBase.getValue(tour.locationIdNumber[i], &keyValue)) {
            printf("%d %s (%.1f, %.1f, %.1f) [%.2f %.2f %.2f] %s / %s\n", keyValue.key,
                   keyValue.robotLocationDescription, keyValue.robotLocation.x, keyValue.robotLocation.y,
                   keyValue.robotLocation.theta, keyValue.gestureTarget.x, keyValue.gestureTarget.y,
                   keyValue.gestureTarget.z, keyValue.preGestureMessageEnglish, keyValue.postGestureMessageEnglish);
        }
    }
    if (knowledgeBase.getValue(99, &keyValue)) printf("location 99?\n");
    knowledgeBase.printToScreen();
    return 0;
}
