//! Unit tests of `commands/lab/server.rs`.

#[test]
fn a_lab_on_every_interface_is_opened_on_the_loopback() {
    let url = |a: &str| lesson11::commands::lab::server::page_url(a.parse().unwrap());
    assert_eq!(url("0.0.0.0:8011"), "http://127.0.0.1:8011/");
    assert_eq!(url("[::]:8011"), "http://[::1]:8011/");
    assert_eq!(url("127.0.0.1:8011"), "http://127.0.0.1:8011/");
    assert_eq!(url("192.168.1.5:80"), "http://192.168.1.5:80/");
}
