// The document's example application (D5.4.2 §6, environmentKnowledgeBaseApplication.cpp),
// as it is written: its include, a local object, no try and no catch, and its loop to
// i <= numberOfLocations. Nothing of ekb in it. scripts/test-loader.sh builds it as it is
// and with -DSTRING_LENGTH=600 (a program built for the 2026-04 header).
#include <utilities/environmentKnowledgeBaseInterface.h>
int main() {
    KeyValueType keyValue;       // structure with key and values
    TourSpecificationType tour;  // list of tour locations
    int idNumber;                // location id
    int i;                       // counter

    /* instantiate the environment knowledge base object                      */
    /* this reads the knowledge value types file and the knowledge base file  */
    /* as specified in the environmentKnowledgeBaseConfiguration.ini file     */
    EnvironmentKnowledgeBase knowledgebase;

    /* verify that the knowledge base was read correctly */
    printf("main: the environment knowledge base data:\n");
    printf("------------------------------------------\n\n");
    knowledgebase.printToScreen();

    printf("main: the environment knowledge base tour:\n");
    printf("------------------------------------------\n\n");
    knowledgebase.getTour(&tour);

    /* query the contents of the knowledge base:                */
    /* retrieve all the locations on a tour                     */
    /* and print them in the order in which they are specified  */
    for (i = 0; i <= tour.numberOfLocations; i++) {
        idNumber = tour.locationIdNumber[i];
        if (knowledgebase.getValue(idNumber, &keyValue) == true) {
            printf("main:\n"
                   "Key                              %-4d \n"
                   "Location Description             %s \n"
                   "Robot Location                   (%.1f, %.1f %.1f)\n"
                   "Gesture Target                   (%.1f, %.1f %.1f) \n"
                   "Pre-Gesture Message English      %s \n"
                   "Pre-Gesture Message isiZulu      %s \n"
                   "Pre-Gesture Message Kinyarwanda  %s \n"
                   "Post-Gesture Message English     %s \n"
                   "Post-Gesture Message isiZulu     %s \n"
                   "Post-Gesture Message Kinyarwanda %s \n\n",
                   keyValue.key, keyValue.robotLocationDescription, keyValue.robotLocation.x,
                   keyValue.robotLocation.y, keyValue.robotLocation.theta, keyValue.gestureTarget.x,
                   keyValue.gestureTarget.y, keyValue.gestureTarget.z, keyValue.preGestureMessageEnglish,
                   keyValue.preGestureMessageIsiZulu, keyValue.preGestureMessageKinyarwanda,
                   keyValue.postGestureMessageEnglish, keyValue.postGestureMessageIsiZulu,
                   keyValue.postGestureMessageKinyarwanda);
        }
    }
}
