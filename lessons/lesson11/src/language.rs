//! The language of the program, Bulgarian or English (`--lang bg|en`, else
//! `LESSON11_LANG`, else the system locale: see the `lang` crate), and the
//! command line's help in Bulgarian.
//!
//! The language is chosen before the command line is parsed, so that
//! `--help` already speaks it: the help's texts are clap's (from the doc
//! comments, in English); in Bulgarian this module puts the Bulgarian texts
//! of the commands and of every option in their place (the tables below,
//! by the option's id), the headings, the usage line and clap's "default"
//! and "possible values" in Bulgarian.

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

/// The help of every option in Bulgarian: `(command, option, text)`, where
/// an empty command stands for every command that has the option, and a
/// named one overrides it (`scenes --force` is not the renders' `--force`).
const OPTIONS_BG: &[(&str, &str, &str)] = &[
    // The scene, size, samples, seed, threads and output of the chapters and `render`.
    (
        "",
        "scene",
        "Име на вградена сцена (вижте `lesson11 scenes`) или път до файл със сцена (.toml). Вграденото име има предимство пред файл със същото име в текущата папка (за файла пишете ./ИМЕ)",
    ),
    (
        "",
        "width",
        "Ширина на картината в пиксели (по подразбиране: тази на сцената)",
    ),
    (
        "",
        "height",
        "Височина на картината в пиксели (по подразбиране: тази на сцената)",
    ),
    (
        "",
        "spp",
        "Проби на пиксел (по подразбиране: тези на сцената)",
    ),
    (
        "",
        "seed",
        "Seed на случайните числа: същият seed дава същата картина, бит по бит",
    ),
    (
        "",
        "threads",
        "Работни нишки (по подразбиране: всички ядра; най-много 4 на ядро, а поне 64 винаги са позволени). Картината не зависи от тях",
    ),
    ("", "out", "Папката за резултатите"),
    (
        "",
        "force",
        "Продължава, въпреки че рендерирането иска повече памет от границата (половината от физическата памет) или повече работа от бюджета (най-много 1e10 лъча, светлинни пътя или мутации)",
    ),
    (
        "",
        "quality",
        "Колко време да отнеме: tiny, quick (по подразбиране) или full",
    ),
    ("", "quick", "Кратко за --quality quick"),
    ("", "full", "Кратко за --quality full"),
    // The integrators and their options (`render`, `stereo`).
    ("", "integrator", "Алгоритъмът, който оценява всеки пиксел"),
    (
        "",
        "max_depth",
        "Максимална дълбочина D на пътя, по конвенцията на Mitsuba: 1 = само светлините, видени направо, 2 = директна светлина, D = най-много D−1 отражения, −1 = без граница; най-много 65535, както във файл със сцена (по подразбиране: тази на сцената; за наивната рекурсия 4, освен ако тази на сцената е крайна). Не важи за direct и ao",
    ),
    (
        "",
        "rr_depth",
        "Руската рулетка може да прекратява пътищата след толкова отражения (по подразбиране: тази на сцената). Не важи за direct и ao",
    ),
    (
        "",
        "branching",
        "Наивна рекурсия: коефициентът на разклоняване N, по един за ниво (последният се повтаря), напр. 16,4,2 (по подразбиране: 8)",
    ),
    (
        "",
        "roulette",
        "Наивна рекурсия: прекратяване с руска рулетка (неотместено) от --rr-depth нататък",
    ),
    (
        "",
        "cutoff",
        "Наивна рекурсия: спиране, щом произведението на BRDF теглата падне под тази стойност (идеята от лекцията; отместено)",
    ),
    (
        "",
        "ao_distance",
        "Ambient occlusion: дължината на лъчите за засенчване, в единиците на сцената (метри; по подразбиране 1)",
    ),
    (
        "",
        "chains",
        "Metropolis: независими вериги на Марков, всяка с равен дял от мутациите (по подразбиране 64 или по една на мутация, ако мутациите са по-малко). Картината не зависи от --threads; разсейването на веригите е нейният EXR на дисперсията",
    ),
    (
        "",
        "bootstrap",
        "Metropolis: независимите пътища на началната оценка (bootstrap), която оценява яркостта b и стартира веригите (по подразбиране: по един на пиксел)",
    ),
    (
        "",
        "large_step_probability",
        "Metropolis: вероятността за голяма стъпка – нов независим път, в [0, 1] (по подразбиране 0.3)",
    ),
    (
        "",
        "mutation_size",
        "Metropolis: стандартното отклонение на малката стъпка в пространството на първичните проби, в (0, 1] (по подразбиране 0.01)",
    ),
    (
        "",
        "photons",
        "photon: трасирани светлинни пътища (по подразбиране 200000); sppm: фотонни пътища на преминаване (по подразбиране 50000)",
    ),
    (
        "",
        "k",
        "photon: оценка на плътността от k-те най-близки фотона (по подразбиране 50)",
    ),
    (
        "",
        "radius",
        "photon: фиксиран радиус на търсене вместо k-те най-близки; sppm: началният радиус (по подразбиране: 1% от диагонала на сцената). В единиците на сцената",
    ),
    (
        "",
        "final_gather",
        "photon: final gathering с толкова BRDF лъча на видима точка (по подразбиране 0: глобалната фотонна карта се чете направо)",
    ),
    (
        "",
        "alpha",
        "sppm: делът α от новите фотони, който се запазва при всяко преминаване, в (0, 1) (по подразбиране 2/3)",
    ),
    (
        "",
        "vpl_paths",
        "vpl: трасирани светлинни пътища; всеки оставя VPL (виртуална точкова светлина) във всеки дифузен връх (по подразбиране 256)",
    ),
    (
        "",
        "clamp",
        "vpl: ограничаване (clamping) на геометричния член G до тази граница (по подразбиране 0: без ограничаване, неотместено)",
    ),
    (
        "",
        "ic_error",
        "irradiance-cache: прагът на грешката a на Ward (по подразбиране 0.3; по-малък: повече записи)",
    ),
    (
        "",
        "ic_rays",
        "irradiance-cache: лъчи по полусферата на запис (по подразбиране 128)",
    ),
    (
        "",
        "ic_gradients",
        "irradiance-cache: градиентите на Ward и Heckbert: записите екстраполират E_i + (n_i × n)·∇_r E_i + (x − x_i)·∇_t E_i от стратифицираните си лъчи, вместо само да усредняват",
    ),
    (
        "",
        "exposure",
        "Експозиция в стъпки за PNG картините (+1 удвоява яркостта); EXR файловете никога не се променят",
    ),
    // `stereo`: the stereo rig, the anaglyphs and the light field.
    (
        "",
        "separation",
        "stereoSeparation: цялото разстояние между очите в единиците на сцената; всяко око се измества с половината (0.065 = очите на човек в сцена в метри)",
    ),
    (
        "",
        "convergence",
        "Разстоянието на нулев паралакс по посоката на гледане: каквото лежи там, се появява в равнината на екрана (по подразбиране: фокусното разстояние на камерата)",
    ),
    (
        "",
        "mode",
        "Кои картини да се запишат, разделени със запетая: red-cyan, half-color, grey, red-blue, red-green, amber-blue, green-magenta, dubois, side-by-side, cross-eyed, over-under, left, right или all",
    ),
    (
        "",
        "desaturate",
        "Обезцветяване на анаглифите, от 0 (цветовете не се променят) до 1 (сиво): лекът за наситени сцени, в които едното око би виждало дупки",
    ),
    (
        "",
        "toe_in",
        "Завърта очите към точката на конвергенция, вместо да измества пирамидите им на видимост (нарочно сбъркано: води до вертикален паралакс)",
    ),
    (
        "",
        "leakage",
        "Пропускането на анаглифните филтри в картините на прозирането (0 = съвършени филтри); записват се като crosstalk-EYE-leakPERCENT.png",
    ),
    (
        "",
        "lf_views",
        "Light field: изгледи по страна на решетката N×N (0 = без light field)",
    ),
    (
        "",
        "lf_aperture",
        "Light field: страната на квадратния отвор, който изгледите покриват, в единиците на сцената",
    ),
    (
        "",
        "lf_downscale",
        "Light field: изгледите се рендерират толкова пъти по-малки от очите (1: размерът на очите, в който слайдовете показват двойката изгледи)",
    ),
    (
        "",
        "lf_spp",
        "Light field: проби на пиксел за всеки изглед (по подразбиране: една шестнадесета от --spp, поне 1; префокусираната картина усреднява всички изгледи, така че има изгледи × толкова)",
    ),
    (
        "",
        "refocus",
        "Light field: дълбочини за префокусиране, разделени със запетая (по подразбиране: половината, веднъж и три пъти разстоянието на конвергенция)",
    ),
    // `render`.
    (
        "",
        "engine",
        "Кой двигател изпълнява --integrator path: този от лекцията (scalar) или wavefront двигателят (пътищата на едно парче вървят заедно; същата картина бит по бит, по-бързо)",
    ),
    (
        "",
        "student",
        "Рендерира с вашия код от exercises/ (naive: задача 10, path-brdf: 11, direct и path-nee: 12, path: 13, light: 14, bdpt: 15, mlt: 16, photon: 17, vpl: 18) до интегратора на рендерера със същата оценка",
    ),
    // `lab`.
    (
        "lab",
        "host",
        "Адресът, на който да слуша. По подразбиране само 127.0.0.1 (тази машина); всеки друг адрес позволява на всяка машина, която го достига, да ползва лабораторията (предупреждение казва това)",
    ),
    ("lab", "port", "Портът (0 избира свободен)"),
    (
        "lab",
        "open",
        "Отваря страницата в браузъра по подразбиране",
    ),
    (
        "lab",
        "scenes",
        "Папка с файлове със сцени (.toml), предлагани до вградените; чете се наново всеки път, когато страницата попита, така че новите файлове се появяват без рестарт",
    ),
    // `scenes`.
    ("scenes", "write", "Записва тази вградена сцена във файл"),
    ("scenes", "to", "Папката, в която да я запише"),
    (
        "scenes",
        "force",
        "Заменя файловете със същото име, които се различават от вградената сцена (вашите промени се губят)",
    ),
    // `bench`.
    (
        "bench",
        "threads",
        "Брой нишки за измерване (разделени със запетая; по подразбиране: 1 и всички ядра)",
    ),
    (
        "bench",
        "spp",
        "Проби на пиксел при измерването върху Cornell box",
    ),
    (
        "bench",
        "no_rays",
        "Пропуска частта за пропускателната способност на лъчите",
    ),
    (
        "bench",
        "no_biased",
        "Пропуска частта за отместените интегратори (фотони, фотонна карта, SPPM, VPL)",
    ),
    (
        "bench",
        "equal_time",
        "Секунди на алгоритъм при сравнението с равно време (0 го пропуска)",
    ),
    (
        "bench",
        "mitsuba",
        "Python с инсталиран Mitsuba 3, за да се отпечата отношението на нашия path tracing към този на Mitsuba в Cornell box (по подразбиране: променливата на средата LESSON11_MITSUBA_PYTHON, иначе `python3`, ако има Mitsuba)",
    ),
    // `exercises`, `hint`, `solution`, `references`.
    (
        "exercises",
        "watch",
        "Следи exercises/src/: проверява задачата отново при всеки запис на файла ѝ и показва резултата и командата за следващата подсказка",
    ),
    (
        "",
        "number",
        "Номерът на задачата (1, 2, …), както го показва `lesson11 exercises`",
    ),
    ("hint", "all", "Показва всички подсказки наведнъж"),
    (
        "hint",
        "reset",
        "Забравя колко подсказки са показани (за всички задачи)",
    ),
    (
        "references",
        "grader_only",
        "Само еталонните картини на проверката (секунди), без тези на сцените door и caustic (минути)",
    ),
    // `slides`.
    (
        "slides",
        "out",
        "Папката с картините на обиколката; слайдовете отиват в OUT/slides/",
    ),
    (
        "slides",
        "src",
        "Папка с по една подпапка с Markdown за всеки език (по подразбиране: ./slides, иначе папката slides/ на проекта)",
    ),
    (
        "slides",
        "quality",
        "Качеството на картините, които се рендерират, когато някои липсват: tiny, quick или full",
    ),
    ("slides", "quick", "Същото като --quality quick"),
    (
        "slides",
        "tiny",
        "Същото като --quality tiny: картини от 32 пиксела за секунди, за проверка на слайдовете",
    ),
    (
        "slides",
        "render",
        "Рендерира всяка картина наново, дори ако всички съществуват",
    ),
    (
        "slides",
        "threads",
        "Работни нишки за рендерирането (по подразбиране: всички ядра)",
    ),
    (
        "slides",
        "lang",
        "Езиците за сглобяване, разделени със запетая (по подразбиране: всяка подпапка на --src)",
    ),
];

/// The help of the values an option lists, in Bulgarian: `(option, value, text)`.
const VALUES_BG: &[(&str, &str, &str)] = &[
    (
        "quality",
        "tiny",
        "Малки картини, малко проби: проверява, че всяка глава работи (секунди)",
    ),
    (
        "quality",
        "quick",
        "По подразбиране: всяка картина се разчита, цялата обиколка за около минута",
    ),
    (
        "quality",
        "full",
        "Осем пъти пробите на quick, за слайдове и материали",
    ),
    (
        "engine",
        "scalar",
        "Path tracing от лекцията: един път от камерата до края му, после следващият",
    ),
    (
        "engine",
        "wavefront",
        "Wavefront двигателят: пътищата на едно парче вървят заедно, по един етап наведнъж (същата картина, по-бързо)",
    ),
    (
        "integrator",
        "direct",
        "Директно осветление: светлините, видени направо, плюс едно отражение (семплиране на светлините и по BRDF с MIS)",
    ),
    (
        "integrator",
        "ao",
        "Ambient occlusion: отворената част от полусферата (не е физически базирано)",
    ),
    (
        "integrator",
        "path",
        "Path tracing: по едно продължение на отражение, семплиране на светлините и по BRDF с MIS",
    ),
    (
        "integrator",
        "path-brdf",
        "Path tracing само с BRDF семплиране (учебно сравнение: светлините се намират случайно)",
    ),
    (
        "integrator",
        "path-nee",
        "Path tracing само със семплиране на светлините, без MIS (учебно сравнение)",
    ),
    (
        "integrator",
        "naive",
        "Наивна рекурсия с Monte Carlo: N лъча при всяко пресичане (вижте --branching), до 1 + N + … + N^(D−1) лъча на проба",
    ),
    (
        "integrator",
        "light",
        "Light tracing: пътищата тръгват от светлините и всеки връх се свързва с камерата",
    ),
    (
        "integrator",
        "bdpt",
        "Bidirectional path tracing: подпътища от камерата и от светлината, всички свързвания, MIS върху всички тях",
    ),
    (
        "integrator",
        "mlt",
        "Metropolis light transport: вериги на Марков върху bidirectional пътища; --spp брои мутациите на пиксел (вижте --chains, --bootstrap, --large-step-probability, --mutation-size)",
    ),
    (
        "integrator",
        "photon",
        "Photon mapping (отместен): фотонни карти от светлинни пътища, оценки на плътността в пресичанията на лъчите от камерата",
    ),
    (
        "integrator",
        "sppm",
        "Stochastic progressive photon mapping (отместен, но състоятелен): --spp преминавания, радиусите се свиват с --alpha",
    ),
    (
        "integrator",
        "vpl",
        "Instant radiosity (отместен при ограничаване): VPL (виртуални точкови светлини) от светлинни пътища, събирани с лъчи за сянка",
    ),
    (
        "integrator",
        "irradiance-cache",
        "Irradiance caching (отместен): индиректната irradiance (облъченост) в няколко записа, интерполирана (Ward)",
    ),
];

/// The Bulgarian help of `command`'s option `id`, if there is one.
fn option_bg(command: &str, id: &str) -> Option<&'static str> {
    let find = |c: &str| {
        OPTIONS_BG
            .iter()
            .find(|(cmd, i, _)| *cmd == c && *i == id)
            .map(|(_, _, text)| *text)
    };
    find(command).or_else(|| find(""))
}

/// `arg` with its Bulgarian help `text`: clap's English "[default: …]" and
/// "[possible values: …]" said in Bulgarian instead, and each listed
/// value's help from [`VALUES_BG`] in the long help.
fn bulgarian_arg(arg: clap::Arg, text: &str) -> clap::Arg {
    // A flag (`--force`) lists neither values nor a default.
    if !arg.get_action().takes_values() {
        return arg.help(text.to_string()).long_help(None::<&str>);
    }
    let id = arg.get_id().as_str().to_string();
    let (mut short, mut long) = (text.to_string(), text.to_string());
    let values: Vec<clap::builder::PossibleValue> = arg
        .get_possible_values()
        .into_iter()
        .filter(|v| !v.is_hide_set())
        .collect();
    if !values.is_empty() && !arg.is_hide_possible_values_set() {
        let names: Vec<&str> = values.iter().map(|v| v.get_name()).collect();
        short.push_str(&format!(" [възможни стойности: {}]", names.join(", ")));
        if values.iter().any(|v| v.get_help().is_some()) {
            long.push_str("\n\nВъзможни стойности:");
            for name in &names {
                let help = VALUES_BG
                    .iter()
                    .find(|(i, v, _)| *i == id && v == name)
                    .map_or("", |(_, _, t)| *t);
                long.push_str(&format!("\n- {name}: {help}"));
            }
        } else {
            long = short.clone();
        }
    }
    let defaults: Vec<String> = arg
        .get_default_values()
        .iter()
        .map(|v| v.to_string_lossy().into_owned())
        .collect();
    if !defaults.is_empty() && !arg.is_hide_default_value_set() {
        let default = format!("[по подразбиране: {}]", defaults.join(", "));
        short.push_str(&format!(" {default}"));
        long.push_str(&format!("\n\n{default}"));
    }
    arg.help(short)
        .long_help(long)
        .hide_default_value(true)
        .hide_possible_values(true)
}

/// The placeholders of `--help` (`<SCENE>`, `<WIDTH>`) in Bulgarian, by the
/// English one; a placeholder not listed keeps its English name (none is
/// left today: a test in `tests/cli.rs` lists them).
const VALUE_NAMES_BG: &[(&str, &str)] = &[
    ("LANG", "ЕЗИК"),
    ("THREADS", "НИШКИ"),
    ("SPP", "ПРОБИ"),
    ("OUT", "ПАПКА"),
    ("WIDTH", "ШИРИНА"),
    ("HEIGHT", "ВИСОЧИНА"),
    ("SEED", "SEED"),
    ("SCENE", "СЦЕНА"),
    ("QUALITY", "КАЧЕСТВО"),
    ("NUMBER", "НОМЕР"),
    ("VPL_PATHS", "ПЪТИЩА"),
    ("RR_DEPTH", "ДЪЛБОЧИНА"),
    ("RADIUS", "РАДИУС"),
    ("PHOTONS", "ФОТОНИ"),
    ("MUTATION_SIZE", "РАЗМЕР"),
    ("MAX_DEPTH", "ДЪЛБОЧИНА"),
    ("LARGE_STEP_PROBABILITY", "ВЕРОЯТНОСТ"),
    ("K", "K"),
    ("INTEGRATOR", "ИНТЕГРАТОР"),
    ("IC_RAYS", "ЛЪЧИ"),
    ("IC_ERROR", "ГРЕШКА"),
    ("FINAL_GATHER", "ЛЪЧИ"),
    ("EXPOSURE", "СТЪПКИ"),
    ("CUTOFF", "ПРАГ"),
    ("CLAMP", "ГРАНИЦА"),
    ("CHAINS", "ВЕРИГИ"),
    ("BRANCHING", "РАЗКЛОНЯВАНЕ"),
    ("BOOTSTRAP", "ПЪТИЩА"),
    ("AO_DISTANCE", "РАЗСТОЯНИЕ"),
    ("ALPHA", "АЛФА"),
    ("TO", "ПАПКА"),
    ("SRC", "ПАПКА"),
    ("SEPARATION", "РАЗСТОЯНИЕ"),
    ("SCENES", "ПАПКА"),
    ("REFOCUS", "ДЪЛБОЧИНИ"),
    ("PYTHON", "PYTHON"),
    ("PORT", "ПОРТ"),
    ("NAME", "ИМЕ"),
    ("MODE", "РЕЖИМ"),
    ("LF_VIEWS", "ИЗГЛЕДИ"),
    ("LF_SPP", "ПРОБИ"),
    ("LF_DOWNSCALE", "ДЕЛИТЕЛ"),
    ("LF_APERTURE", "АПЕРТУРА"),
    ("LEAKAGE", "ДЯЛ"),
    ("HOST", "АДРЕС"),
    ("EQUAL_TIME", "СЕКУНДИ"),
    ("ENGINE", "ДВИГАТЕЛ"),
    ("DESATURATE", "ДЯЛ"),
    ("CONVERGENCE", "РЕЖИМ"),
];

/// `arg` with its `--help` placeholder in Bulgarian ([`VALUE_NAMES_BG`]).
fn bulgarian_value_name(arg: clap::Arg) -> clap::Arg {
    if !arg.get_action().takes_values() {
        return arg;
    }
    let english = match arg.get_value_names() {
        Some([name]) => name.to_string(),
        Some(_) => return arg,
        None => arg.get_id().as_str().to_ascii_uppercase(),
    };
    match VALUE_NAMES_BG.iter().find(|(en, _)| *en == english) {
        Some((_, bg)) => arg.value_name(*bg),
        None => arg,
    }
}

/// `command`'s options with their Bulgarian help, where [`OPTIONS_BG`] has it.
fn localize_options(command: clap::Command) -> clap::Command {
    let name = command.get_name().to_string();
    command.mut_args(|arg| match option_bg(&name, arg.get_id().as_str()) {
        Some(text) => bulgarian_value_name(bulgarian_arg(arg, text)),
        None => bulgarian_value_name(arg),
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

/// The same for a command with arguments (`hint N`).
const TEMPLATE_BG_ARGS: &str = "\
{before-help}{about-with-newline}
Употреба: {usage}

Аргументи:
{positionals}

Опции:
{options}{after-help}";

/// The layout of `command`'s help in Bulgarian.
fn template_bg(command: &clap::Command) -> &'static str {
    if command.has_subcommands() {
        TEMPLATE_BG
    } else if command.get_positionals().next().is_some() {
        TEMPLATE_BG_ARGS
    } else {
        TEMPLATE_BG_LEAF
    }
}

/// A built command's usage line in Bulgarian: clap's, with its words
/// (`[OPTIONS]`, `[COMMAND]`) in Bulgarian.
fn usage_bg(command: &mut clap::Command) -> String {
    let usage = command.render_usage().to_string();
    let usage = usage.trim_start_matches("Usage:").trim();
    usage
        .replace("[OPTIONS]", "[ОПЦИИ]")
        .replace("[COMMAND]", "[КОМАНДА]")
        .replace("<COMMAND>", "<КОМАНДА>")
}

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
        let a = a
            .help(lang_help(language))
            .hide_possible_values(language == Lang::Bg);
        match language {
            Lang::En => a,
            Lang::Bg => bulgarian_value_name(a),
        }
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
            let template = template_bg(&sub);
            let sub = localize_options(sub.help_template(template));
            match about {
                Some(text) => sub.about(text).long_about(None),
                None => sub,
            }
        });
    // clap adds --help and --version when the command is built, and the
    // global --lang to every subcommand.
    command.build();
    let help = ABOUT_BG
        .iter()
        .find(|(n, _)| *n == "help")
        .map_or("", |(_, t)| *t);
    let usage = usage_bg(&mut command);
    command
        .override_usage(usage)
        .mut_arg("help", |a| {
            a.help("Показва помощта").long_help(None::<&str>)
        })
        .mut_arg("version", |a| a.help("Показва версията"))
        .mut_subcommand("help", |sub| sub.about(help))
        .mut_subcommands(|mut sub| {
            let usage = usage_bg(&mut sub);
            let sub = sub.override_usage(usage);
            if sub.get_arguments().any(|a| a.get_id() == "help") {
                sub.mut_arg("help", |a| {
                    a.help("Показва помощта").long_help(None::<&str>)
                })
            } else {
                sub
            }
        })
}
