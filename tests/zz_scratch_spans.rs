use toml::de::{DeTable, DeValue};
use toml::Spanned;

fn dump(text: &str, v: &Spanned<DeValue>, indent: usize) {
    let s = v.span();
    match v.get_ref() {
        DeValue::Table(t) => {
            println!("{:indent$}table {:?} {:?}", "", s, &text[s.clone()].chars().take(30).collect::<String>(), indent = indent);
            for (k, val) in t.iter() {
                println!("{:indent$}key {} {:?}", "", k.get_ref(), k.span(), indent = indent + 2);
                dump(text, val, indent + 4);
            }
        }
        DeValue::Array(a) => {
            println!("{:indent$}array {:?}", "", s, indent = indent);
            for val in a.iter() { dump(text, val, indent + 2); }
        }
        _ => println!("{:indent$}leaf {:?} {:?}", "", s, &text[s.clone()], indent = indent),
    }
}

#[test]
fn spans() {
    let text = "a = 1\n[run]\nname = 'x'\n\n[[wall]]\nkind = 'plane'\nmotion = { kind = 'linear', v = [1,2] }\n[[wall]]\nkind = 'box'\n[[spheres]]\nsizes = [\n  { d = 1 },\n  { d = 2 },\n]\n[x.y]\nz.w = 3\n";
    let t = DeTable::parse(text).unwrap();
    let span = t.span();
    let v = Spanned::new(span, DeValue::Table(t.into_inner()));
    dump(text, &v, 0);
}
