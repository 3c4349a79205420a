// utilities/environmentKnowledgeBaseInterface.h: ekb's drop-in for the document's class, as
// the document (§6) and the robot's example application include it. It is
// ../environmentKnowledgeBaseInterface.h, which says what it does.
#include "../environmentKnowledgeBaseInterface.h"
