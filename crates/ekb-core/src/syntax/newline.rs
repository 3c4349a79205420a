//! Finding where a line ends: the one search made on every line of a file.

/// The index of the first newline in `bytes`, if there is one.
#[inline]
pub fn find(bytes: &[u8]) -> Option<usize> {
    memchr::memchr(b'\n', bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_first_newline_wherever_it_is() {
        for len in 0..80 {
            let mut bytes = vec![b'x'; len];
            assert_eq!(find(&bytes), None, "none in {len}");
            for at in 0..len {
                bytes[at] = b'\n';
                assert_eq!(find(&bytes), Some(at), "at {at} of {len}");
                // A later one changes nothing.
                if at + 1 < len {
                    bytes[len - 1] = b'\n';
                    assert_eq!(find(&bytes), Some(at), "at {at} of {len}, and last");
                    bytes[len - 1] = b'x';
                }
                bytes[at] = b'x';
            }
        }
    }

    #[test]
    fn other_bytes_are_not_newlines() {
        let bytes: Vec<u8> = (0..=255u8).filter(|&b| b != b'\n').collect();
        assert_eq!(find(&bytes), None);
        assert_eq!(find(&[0x8a; 40]), None);
    }
}
