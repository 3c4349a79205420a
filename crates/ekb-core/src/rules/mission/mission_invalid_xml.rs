use crate::diagnostic::Diagnostic;
use crate::mission::tree::Mission;
use crate::mission::xml;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a mission file that BehaviorTree.CPP cannot load at all: XML that is not
    /// well-formed (a tag not closed, an attribute without quotes, a stray `&`), or a
    /// document whose root element is not `<root>`.
    ///
    /// ## Why it matters
    /// The robot loads the mission when it starts; on such a file it stops with an
    /// exception before the tour begins, and no visitor is ever greeted.
    ///
    /// ## Example
    /// ```xml
    /// <root BTCPP_format="4" main_tree_to_execute="TourGuide">
    ///   <BehaviorTree ID="TourGuide">
    ///     <Sequence>
    ///   </BehaviorTree>
    /// </root>
    /// ```
    /// `<Sequence>` is never closed.
    pub static MISSION_INVALID_XML = {
        name: "mission-invalid-xml",
        category: Mission,
        severity: Error,
        fixable: false,
        summary: "the mission is not well-formed XML, or its root element is not `<root>`",
    };
}

/// The mission in `text`, or the finding that says why BehaviorTree.CPP cannot load it.
pub fn check(text: &str) -> Result<Mission, Box<Diagnostic>> {
    let root = xml::parse(text).map_err(|error| {
        Box::new(
            Diagnostic::new(
                &MISSION_INVALID_XML,
                error.span,
                format!(
                    "the mission is not well-formed XML ({}): the robot cannot load it and \
                 stops before the tour begins",
                    error.message
                ),
            )
            .with_help("correct the XML here; an XML-aware editor shows where tags open and close"),
        )
    })?;
    if root.name != "root" {
        return Err(Box::new(
            Diagnostic::new(
                &MISSION_INVALID_XML,
                root.name_span,
                format!(
                    "the document's root element is <{}>: BehaviorTree.CPP requires <root>, so \
                 the robot cannot load the mission",
                    root.name
                ),
            )
            .with_help("wrap the trees in <root BTCPP_format=\"4\" main_tree_to_execute=\"…\">"),
        ));
    }
    Ok(Mission::new(root))
}
