//! The language of the program, Bulgarian or English (`--lang bg|en`, else
//! `LESSON11_LANG`, else the system locale: see the `lang` crate), and the
//! command line's help in Bulgarian.
//!
//! The language is chosen before the command line is parsed, so that
//! `--help` already speaks it: the help's texts are clap's (from the doc
//! comments, in English); in Bulgarian this module puts the Bulgarian texts
//! of the commands and of the common options in their place, and the
//! headings of the help in Bulgarian. A chapter's own options keep their
//! English help for now.

use lang::Lang;

/// The language `args` ask for with `--lang X` or `--lang=X` (the last one
/// wins), if any names one.
pub fn from_args(args: &[String]) -> Option<Lang> {
    let mut found = None;
    for (i, a) in args.iter().enumerate() {
        if a == "--" {
            break;
        }
        let value = match a.strip_prefix("--lang") {
            Some("") => args.get(i + 1).map(String::as_str),
            Some(rest) => rest.strip_prefix('='),
            None => None,
        };
        if let Some(l) = value.and_then(Lang::parse) {
            found = Some(l);
        }
    }
    found
}

/// Chooses the language for this run (also for the programs it starts, which
/// read `LESSON11_LANG`: the grader's `cargo test`): `--lang`, else the
/// environment.
pub fn choose(args: &[String]) -> Lang {
    let language = from_args(args).unwrap_or_else(lang::current);
    lang::set(language);
    language
}

/// The help of each command in Bulgarian, by the command's name.
const ABOUT_BG: &[(&str, &str)] = &[
    (
        "tour",
        "Минава през лекцията по ред и записва всяка картина (по подразбиране)",
    ),
    (
        "stereo",
        "1 · Стереоскопия: две очи, анаглифи, картини една до друга, преливане (crosstalk) и светлинно поле",
    ),
    (
        "gi-effects",
        "2 · Ефекти на глобалното осветление: директна светлина, ambient occlusion, пълно GI, само индиректната светлина и нашата Cornell box срещу тази на Mitsuba",
    ),
    (
        "brdf",
        "3 · BRDF-и: лобове, насоченото албедо на нормиран и ненормиран Phong, симетричност, галерия",
    ),
    (
        "rendering-equation",
        "4 · Транспортното уравнение: наивна рекурсия с Monte Carlo, лъчите ѝ на пиксел и как да я спрем",
    ),
    (
        "path",
        "5 · Path tracing: стълба от проби на пиксел; избор по BRDF, по лампите и MIS, и на сцената на Veach",
    ),
    (
        "light",
        "6 · Light tracing и каустиката, която намират само светлинните пътища",
    ),
    (
        "bdpt",
        "7 · Bidirectional path tracing и неговите стратегии (s, t)",
    ),
    (
        "compare",
        "8 · Всички алгоритми при равно време: RMSE спрямо независим еталон, графики на сходимостта",
    ),
    (
        "biased",
        "9 · Неотместени и отместени при равно време: photon mapping, SPPM, instant radiosity, irradiance caching",
    ),
    (
        "render",
        "Рендерира една сцена с един интегратор в PNG (за гледане) и EXR (за измерване)",
    ),
    (
        "lab",
        "Лекцията на живо в браузъра: прогресивно рендериране с параметрите му, стерео двойка, лобове и албедо на BRDF и инспектор на пътищата",
    ),
    (
        "scenes",
        "Изброява вградените сцени или записва една във файл, който да редактирате",
    ),
    (
        "bench",
        "Измерва рендерера: лъчи в секунда при големи мрежи, проби в секунда в Cornell box",
    ),
    (
        "exercises",
        "Задачите: кои минават, кои не минават, кои не са започнати, и коя е следващата",
    ),
    ("hint", "Следващата подсказка за задача N"),
    (
        "solution",
        "Еталонното решение на задача N, щом вашето минава",
    ),
    (
        "references",
        "За преподаватели: прави наново еталонните картини на проверката (средно и дисперсия в EXR)",
    ),
    (
        "slides",
        "Сглобява слайдовете на лекцията (български и английски) в HTML с рендерираните картини",
    ),
    (
        "help",
        "Показва това съобщение или помощта за дадената команда",
    ),
];

/// The help of the options most commands share (the chapters' and the
/// tour's scene, size, samples, seed, threads, output), in Bulgarian.
const OPTIONS_BG: &[(&str, &str)] = &[
    (
        "scene",
        "Име на вградена сцена (вижте `lesson11 scenes`) или път до файл със сцена (.toml). Вграденото име има предимство пред файл със същото име в текущата папка (за файла пишете ./ИМЕ)",
    ),
    (
        "width",
        "Ширина на картината в пиксели (по подразбиране: тази на сцената)",
    ),
    (
        "height",
        "Височина на картината в пиксели (по подразбиране: тази на сцената)",
    ),
    ("spp", "Проби на пиксел (по подразбиране: тези на сцената)"),
    (
        "seed",
        "Seed на случайните числа: същият seed дава същата картина, бит по бит",
    ),
    (
        "threads",
        "Работни нишки (по подразбиране: всички ядра; най-много 4 на ядро, а поне 64 винаги са позволени). Картината не зависи от тях",
    ),
    ("out", "Папката за резултатите"),
    (
        "force",
        "Продължава, въпреки че рендерирането иска повече памет от границата (половината от физическата памет) или наивната рекурсия повече лъчи от бюджета си",
    ),
    (
        "quality",
        "Колко време да отнеме: tiny, quick (по подразбиране) или full",
    ),
    ("quick", "Кратко за --quality quick"),
    ("full", "Кратко за --quality full"),
];

/// `command`'s options of [`OPTIONS_BG`] with their Bulgarian help.
fn localize_options(command: clap::Command) -> clap::Command {
    OPTIONS_BG.iter().fold(command, |c, (id, text)| {
        if c.get_arguments().any(|a| a.get_id() == id) {
            c.mut_arg(*id, |a| a.help(*text).long_help(None::<&str>))
        } else {
            c
        }
    })
}

/// The help's layout with Bulgarian headings (clap's own are English).
const TEMPLATE_BG: &str = "\
{before-help}{about-with-newline}
Употреба: {usage}

Команди:
{subcommands}

Опции:
{options}{after-help}";

/// The same for a command without subcommands.
const TEMPLATE_BG_LEAF: &str = "\
{before-help}{about-with-newline}
Употреба: {usage}

Опции:
{options}{after-help}";

/// The text of `--lang` in `--help`.
pub fn lang_help(language: Lang) -> &'static str {
    language.pick(
        "The language: bg (Bulgarian) or en (English); default: LESSON11_LANG, else the system locale (LANG starting with bg: Bulgarian)",
        "Езикът: bg (български) или en (английски); по подразбиране LESSON11_LANG, иначе езикът на системата (LANG, започващ с bg: български)",
    )
}

/// `command` with its help in `language` (see the module doc).
pub fn localize(command: clap::Command, language: Lang) -> clap::Command {
    let command = command.mut_arg("lang", |a| {
        a.help(lang_help(language))
            .hide_possible_values(language == Lang::Bg)
    });
    if language == Lang::En {
        return command;
    }
    let mut command = command
        .about("Лекция 11: стереоскопия, BRDF-и, транспортното уравнение, path tracing, light tracing и bidirectional path tracing и отместените алгоритми — рендерирани.")
        .long_about("Лекция 11: стереоскопия, BRDF-и, транспортното уравнение, path tracing, light tracing и bidirectional path tracing и отместените алгоритми — рендерирани.\n\nБез команда минава през цялата лекция с бързи настройки и записва картините ѝ в out/lesson11/ (отворете out/lesson11/index.html).")
        .help_template(TEMPLATE_BG)
        .disable_help_subcommand(false)
        .mut_subcommands(|sub| {
            let about = ABOUT_BG
                .iter()
                .find(|(name, _)| *name == sub.get_name())
                .map(|(_, text)| *text);
            let template = if sub.has_subcommands() {
                TEMPLATE_BG
            } else {
                TEMPLATE_BG_LEAF
            };
            let sub = localize_options(sub.help_template(template));
            match about {
                Some(text) => sub.about(text).long_about(None),
                None => sub,
            }
        })
        ;
    // clap adds --help and --version when the command is built.
    command.build();
    let help = ABOUT_BG
        .iter()
        .find(|(n, _)| *n == "help")
        .map_or("", |(_, t)| *t);
    command
        .mut_arg("help", |a| {
            a.help("Показва помощта").long_help(None::<&str>)
        })
        .mut_arg("version", |a| a.help("Показва версията"))
        .mut_subcommand("help", |sub| sub.about(help))
}
