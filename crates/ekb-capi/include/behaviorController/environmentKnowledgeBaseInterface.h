// behaviorController/environmentKnowledgeBaseInterface.h: ekb's drop-in for the document's class, as
// the robot's behaviorController node includes it. It is
// ../environmentKnowledgeBaseInterface.h, which says what it does.
#include "../environmentKnowledgeBaseInterface.h"
