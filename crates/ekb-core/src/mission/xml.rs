//! The mission's XML as a tree of elements with their places in the file, read with
//! `roxmltree`: element names, attributes and their values, each with its byte span, so
//! that a finding points at the line and column of what it is about.

use crate::syntax::Span;

/// Elements nested deeper than this are refused: a behaviour tree is a few levels deep,
/// and everything that walks the tree recurses on it.
pub const MAX_DEPTH: usize = 200;

/// More nodes than this (elements, text, comments) are refused, so that memory stays
/// bounded on any input.
const MAX_NODES: u32 = 4_000_000;

/// An element with more attributes than this is refused before the XML is parsed:
/// roxmltree compares each attribute with those before it (a duplicate is an error), so
/// 200,000 attributes on one element took minutes. A BehaviorTree.CPP node has a handful.
pub const MAX_ATTRIBUTES: usize = 256;

/// An attribute as written, its value unescaped.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Attribute {
    pub name: String,
    pub value: String,
    pub name_span: Span,
    pub value_span: Span,
}

/// An element and what it holds.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Element {
    /// The tag name (without a namespace prefix).
    pub name: String,
    /// Where the tag name is written in the start tag.
    pub name_span: Span,
    pub attributes: Vec<Attribute>,
    /// The child elements (text and comments are left out).
    pub children: Vec<Element>,
}

impl Element {
    pub fn attribute(&self, name: &str) -> Option<&Attribute> {
        self.attributes.iter().find(|a| a.name == name)
    }

    pub fn value(&self, name: &str) -> Option<&str> {
        self.attribute(name).map(|a| a.value.as_str())
    }

    /// The elements of this one and below, depth first, in the order written.
    pub fn descendants(&self) -> impl Iterator<Item = &Element> {
        let mut stack = vec![self];
        std::iter::from_fn(move || {
            let element = stack.pop()?;
            stack.extend(element.children.iter().rev());
            Some(element)
        })
    }
}

/// Why a text is no XML document that ekb can read: what is wrong, and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct XmlError {
    pub message: String,
    pub span: Span,
}

/// More `&` than this that start no entity are not escaped one by one (each costs a
/// parse): the next is reported as an error.
const MAX_BARE_AMPERSANDS: usize = 16;

/// Parses `text` (a byte-order mark is allowed) and gives its root element.
///
/// tinyxml2, which BehaviorTree.CPP reads the mission with, keeps a `&` that starts no
/// entity it knows as it is (`_description="Fish & Chips"`), where roxmltree refuses the
/// document: each such `&` is escaped and the document parsed again, and every place
/// mapped back to `text`.
pub fn parse(text: &str) -> Result<Element, XmlError> {
    if let Some(name) = first_with_too_many_attributes(text) {
        return Err(XmlError {
            message: format!(
                "this element has more than {MAX_ATTRIBUTES} attributes: no behaviour-tree \
                 node has, and ekb does not read further"
            ),
            span: name,
        });
    }
    let mut patched = std::borrow::Cow::Borrowed(text);
    // Where each escaped `&` is in `patched`, in increasing order.
    let mut escaped: Vec<usize> = Vec::new();
    loop {
        let bare = match parse_once(&patched) {
            Ok(mut root) => {
                map_spans(&mut root, &escaped);
                return Ok(root);
            }
            Err((error, bare)) => match bare {
                Some(at) if escaped.len() < MAX_BARE_AMPERSANDS => at,
                _ => {
                    let span = error.span;
                    return Err(XmlError {
                        span: Span::empty_at(original(&escaped, span.start as usize)),
                        ..error
                    });
                }
            },
        };
        patched.to_mut().insert_str(bare + 1, "amp;");
        escaped.push(bare);
    }
}

/// The name of the first start tag with more than [`MAX_ATTRIBUTES`] attributes, in one
/// pass over `text`: an attribute is counted by its `=` outside quotes. Comments, CDATA,
/// processing instructions and declarations (`<!DOCTYPE`) are skipped, end tags are not
/// counted; what is not well-formed is left to the parser to report.
fn first_with_too_many_attributes(text: &str) -> Option<Span> {
    let bytes = text.as_bytes();
    let mut at = 0;
    while let Some(found) = memchr::memchr(b'<', &bytes[at..]) {
        let open = at + found;
        let rest = &text[open..];
        let skip_to = |end: &str| rest.find(end).map_or(bytes.len(), |i| open + i + end.len());
        at = if rest.starts_with("<!--") {
            skip_to("-->")
        } else if rest.starts_with("<![CDATA[") {
            skip_to("]]>")
        } else if rest.starts_with("<?") {
            skip_to("?>")
        } else if rest.starts_with("<!") || rest.starts_with("</") {
            open + 2
        } else {
            let (end, attributes) = start_tag_attributes(bytes, open + 1);
            if attributes > MAX_ATTRIBUTES {
                let name_end = rest[1..]
                    .find(|c: char| c.is_whitespace() || c == '>' || c == '/')
                    .map_or(bytes.len(), |i| open + 1 + i);
                return Some(Span::new(open + 1, name_end));
            }
            end
        };
    }
    None
}

/// Where the start tag from `from` ends (after its `>`) and how many `=` it has outside
/// quotes.
fn start_tag_attributes(bytes: &[u8], from: usize) -> (usize, usize) {
    let (mut count, mut quote) = (0, None);
    for (i, &byte) in bytes.iter().enumerate().skip(from) {
        match (quote, byte) {
            (Some(open), _) if byte == open => quote = None,
            (Some(_), _) => {}
            (None, b'"' | b'\'') => quote = Some(byte),
            (None, b'=') => count += 1,
            (None, b'>') => return (i + 1, count),
            // A `<` outside quotes: not a start tag that ends; the parser says so.
            (None, b'<') => return (i, count),
            _ => {}
        }
    }
    (bytes.len(), count)
}

/// The offset in the original text of `at` in the text with `escaped` escaped.
fn original(escaped: &[usize], at: usize) -> usize {
    at - 4 * escaped.iter().filter(|&&amp| amp < at).count()
}

fn map_spans(element: &mut Element, escaped: &[usize]) {
    if escaped.is_empty() {
        return;
    }
    let map = |span: &mut Span| {
        *span = Span::new(
            original(escaped, span.start as usize),
            original(escaped, span.end as usize),
        )
    };
    map(&mut element.name_span);
    for attribute in &mut element.attributes {
        map(&mut attribute.name_span);
        map(&mut attribute.value_span);
    }
    for child in &mut element.children {
        map_spans(child, escaped);
    }
}

/// One parse; on an error, also where the `&` is if it is one that starts no entity.
fn parse_once(text: &str) -> Result<Element, (XmlError, Option<usize>)> {
    let options = roxmltree::ParsingOptions {
        // tinyxml2, which BehaviorTree.CPP uses, skips a DOCTYPE; entities stay bounded.
        allow_dtd: true,
        nodes_limit: MAX_NODES,
        ..roxmltree::ParsingOptions::default()
    };
    let document = roxmltree::Document::parse_with_options(text, options).map_err(|error| {
        let position = error.pos();
        let at = offset_of(text, position.row, position.col);
        let bare = matches!(
            error,
            roxmltree::Error::MalformedEntityReference(_)
                | roxmltree::Error::UnknownEntityReference(..)
        ) && text[at..].starts_with('&');
        let error = XmlError {
            message: describe(&error),
            span: Span::empty_at(at),
        };
        (error, bare.then_some(at))
    })?;
    let root = document.root_element();
    if let Some(node) = first_too_deep(root) {
        return Err((
            XmlError {
                message: format!(
                    "elements are nested more than {MAX_DEPTH} deep: no behaviour tree is, \
                     and ekb does not read further"
                ),
                span: name_span(node),
            },
            None,
        ));
    }
    Ok(convert(root))
}

/// The first element nested deeper than [`MAX_DEPTH`], found in one pass: the stack
/// holds the current element's ancestors.
fn first_too_deep<'a, 'i>(root: roxmltree::Node<'a, 'i>) -> Option<roxmltree::Node<'a, 'i>> {
    let mut ancestors: Vec<roxmltree::NodeId> = Vec::new();
    for node in root.descendants().filter(roxmltree::Node::is_element) {
        let parent = node.parent_element().map(|p| p.id());
        while !ancestors.is_empty() && ancestors.last().copied() != parent {
            ancestors.pop();
        }
        ancestors.push(node.id());
        if ancestors.len() > MAX_DEPTH + 1 {
            return Some(node);
        }
    }
    None
}

/// The element `node` and all below it, in our own terms. The depth is bounded above.
fn convert(node: roxmltree::Node<'_, '_>) -> Element {
    Element {
        name: node.tag_name().name().to_string(),
        name_span: name_span(node),
        attributes: node
            .attributes()
            .map(|attribute| Attribute {
                name: attribute.name().to_string(),
                value: attribute.value().to_string(),
                name_span: Span::new(attribute.range_qname().start, attribute.range_qname().end),
                value_span: Span::new(attribute.range_value().start, attribute.range_value().end),
            })
            .collect(),
        children: node
            .children()
            .filter(roxmltree::Node::is_element)
            .map(convert)
            .collect(),
    }
}

/// The span of an element's tag name as written (a prefix included): just after its `<`.
fn name_span(node: roxmltree::Node<'_, '_>) -> Span {
    let start = node.range().start + 1;
    let rest = node.document().input_text().get(start..).unwrap_or("");
    let length = rest
        .find(|c: char| c.is_whitespace() || c == '>' || c == '/')
        .unwrap_or(rest.len());
    Span::new(start, start + length)
}

/// roxmltree's message, without the position it appends (the finding has its own).
fn describe(error: &roxmltree::Error) -> String {
    let text = error.to_string();
    let position = format!(" at {}", error.pos());
    text.strip_suffix(&position).unwrap_or(&text).to_string()
}

/// The byte offset of a 1-based row and column (in characters), clamped to the text.
fn offset_of(text: &str, row: u32, column: u32) -> usize {
    let line_start = text
        .match_indices('\n')
        .nth((row as usize).saturating_sub(2))
        .map_or(0, |(at, _)| at + 1);
    let line_start = if row <= 1 { 0 } else { line_start };
    text[line_start..]
        .char_indices()
        .nth((column as usize).saturating_sub(1))
        .map_or(text.len(), |(at, _)| line_start + at)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spans_point_at_names_and_values() {
        let text =
            "<root a=\"1\">\n  <Sequence>\n    <SayText name=\"4\"/>\n  </Sequence>\n</root>";
        let root = parse(text).unwrap();
        assert_eq!(root.name_span.text(text), "root");
        let say = &root.children[0].children[0];
        assert_eq!(say.name_span.text(text), "SayText");
        let name = say.attribute("name").unwrap();
        assert_eq!(name.name_span.text(text), "name");
        assert_eq!(name.value_span.text(text), "4");
        let names: Vec<&str> = root.descendants().map(|e| e.name.as_str()).collect();
        assert_eq!(names, ["root", "Sequence", "SayText"]);
    }

    #[test]
    fn errors_have_a_place() {
        let text = "<root>\n  <Sequence>\n  </Sequenc>\n</root>";
        let error = parse(text).unwrap_err();
        assert_eq!(
            &text[..error.span.start as usize],
            "<root>\n  <Sequence>\n  "
        );
        assert!(error.message.contains("Sequence"), "{}", error.message);
        assert!(parse("").is_err());
        assert!(parse("\u{feff}<root/>").is_ok());
    }

    #[test]
    fn a_bare_ampersand_is_kept_as_behaviortree_cpp_keeps_it() {
        let text = "<root>\n  <A _d=\"Fish & Chips\" name=\"a&b;\"/>\n  <B x=\"&amp;\"/>\n</root>";
        let root = parse(text).unwrap();
        let a = &root.children[0];
        assert_eq!(a.value("_d"), Some("Fish & Chips"));
        assert_eq!(a.value("name"), Some("a&b;"));
        let name = a.attribute("name").unwrap();
        assert_eq!(name.value_span.text(text), "a&b;");
        assert_eq!(root.children[1].name_span.text(text), "B");
        // Other errors keep their place in the text as written.
        let broken = "<root a=\"&\">\n</rot>";
        let error = parse(broken).unwrap_err();
        assert_eq!(&broken[..error.span.start as usize], "<root a=\"&\">\n");
    }

    #[test]
    fn deep_nesting_is_refused_not_recursed() {
        let depth = 100_000;
        let text = format!("{}{}", "<a>".repeat(depth), "</a>".repeat(depth));
        let error = parse(&text).unwrap_err();
        assert!(error.message.contains("nested"), "{}", error.message);
    }

    #[test]
    fn an_element_with_too_many_attributes_is_refused_before_parsing() {
        let element = |n: usize| {
            let attributes: String = (0..n).map(|i| format!(" a{i}='x=y'")).collect();
            format!(
                "<root><!-- <a {} --><Sequence{attributes}/></root>",
                "b=1 ".repeat(300)
            )
        };
        assert!(parse(&element(MAX_ATTRIBUTES)).is_ok());
        for count in [MAX_ATTRIBUTES + 1, 200_000] {
            let text = element(count);
            let error = parse(&text).unwrap_err();
            assert!(
                error.message.contains("more than 256 attributes"),
                "{}",
                error.message
            );
            assert_eq!(
                &text[error.span.start as usize..error.span.end as usize],
                "Sequence"
            );
        }
    }

    #[test]
    fn offsets_of_rows_and_columns() {
        let text = "ab\nçd\nef";
        assert_eq!(offset_of(text, 1, 1), 0);
        assert_eq!(offset_of(text, 2, 2), 5);
        assert_eq!(offset_of(text, 3, 2), 8);
        assert_eq!(offset_of(text, 9, 9), text.len());
    }
}
