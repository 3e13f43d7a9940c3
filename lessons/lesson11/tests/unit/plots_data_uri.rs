//! Unit tests of `plots/data_uri.rs`.

use lesson11::plots::data_uri::*;

/// The test vectors of RFC 4648, section 10.
#[test]
fn rfc_4648_vectors() {
    for (text, encoded) in [
        ("", ""),
        ("f", "Zg=="),
        ("fo", "Zm8="),
        ("foo", "Zm9v"),
        ("foob", "Zm9vYg=="),
        ("fooba", "Zm9vYmE="),
        ("foobar", "Zm9vYmFy"),
    ] {
        assert_eq!(base64(text.as_bytes()), encoded, "{text:?}");
    }
    assert_eq!(base64(&[0xff, 0xfe, 0xfd]), "//79");
}
