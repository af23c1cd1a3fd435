using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using System.Threading;
using AvatarGo.Core;

namespace AvatarGo.Cli.Fuzzing;

/// <summary>
/// Runs one target: first the corpus files of that target (previous failures, which must now pass), then the
/// crafted edge cases, then seeded mutations until the time or the input budget is spent. An input fails when it
/// throws anything but a one-line <see cref="FormatException"/> from the parser, when what the parser accepted fails
/// in a later stage (<see cref="FuzzTarget.Check"/>), or when it takes longer than the slow limit (1 s). Each kind of
/// failure (exception type and the core method that threw it, or "slow") is minimised once and saved to the corpus.
/// </summary>
internal sealed class FuzzRunner
{
    private readonly FuzzTarget _target;
    private readonly FuzzOptions _options;
    private readonly TextWriter _log;
    private readonly Dictionary<string, FuzzFinding> _findings = new(StringComparer.Ordinal);

    // Watched by the watchdog thread: an input that runs far beyond the slow limit (a hang) is saved before the
    // process is ended, since it cannot be interrupted.
    private volatile string _current;
    private long _currentStart;

    public FuzzRunner(FuzzTarget target, FuzzOptions options, TextWriter log)
    {
        _target = target;
        _options = options;
        _log = log;
    }

    public FuzzReport Run()
    {
        var report = new FuzzReport(_target.Name);
        var clock = Stopwatch.StartNew();
        using var watchdog = new Timer(_ => Watch(), null, 1000, 1000);

        foreach (string file in CorpusFiles())
            Record(report, Classify(File.ReadAllText(file)), File.ReadAllText(file), "corpus " + Path.GetFileName(file), corpus: true);

        WarmUp(report);
        if (_options.Crafted)
            foreach (CraftedInput c in _target.Crafted(_target.Seeds))
            {
                _log.WriteLine($"  {_target.Name}: crafted: {c.Name}");
                Record(report, Classify(c.Text), c.Text, "crafted: " + c.Name, corpus: false);
            }

        var seeds = new List<string>(_target.Seeds);
        foreach (string file in CorpusFiles()) seeds.Add(File.ReadAllText(file));
        var mutator = new Mutator(seeds, _target.Dictionary, _target.MaxInputLength);
        long lastLog = 0;
        for (long i = 0; i < _options.MaxInputs && clock.Elapsed < _options.Duration; i++)
        {
            string input = mutator.Generate(_options.Seed, i);
            Record(report, Classify(input), input, $"input {i} of seed {_options.Seed}", corpus: false);
            report.Generated++;
            if (clock.ElapsedMilliseconds - lastLog > 10000)
            {
                lastLog = clock.ElapsedMilliseconds;
                _log.WriteLine($"  {_target.Name}: {report.Generated:N0} inputs in {clock.Elapsed.TotalSeconds:0} s, {report.Failures} failing");
            }
        }
        report.Seconds = clock.Elapsed.TotalSeconds;
        report.Findings.AddRange(_findings.Values);
        return report;
    }

    // The 1 s limit is about the parsers, not the JIT: the crafted cases (some of them megabytes) would otherwise run in
    // unoptimised first-tier code. The seeds go through the whole oracle for a second, then the runtime gets a moment
    // to install optimised code. A seed that fails is a failure like any other.
    private void WarmUp(FuzzReport report)
    {
        var clock = Stopwatch.StartNew();
        while (clock.ElapsedMilliseconds < 1000)
            foreach (string seed in _target.Seeds)
            {
                Outcome outcome = Classify(seed);
                if (outcome.Bucket == null) continue;
                Record(report, outcome, seed, "seed", corpus: false);
                return;
            }
        Thread.Sleep(250);
    }

    /// <summary>Runs the <paramref name="index"/>-th generated input alone (to reproduce a crash of the whole process).</summary>
    public Outcome Replay(long index, out string input)
    {
        var seeds = new List<string>(_target.Seeds);
        foreach (string file in CorpusFiles()) seeds.Add(File.ReadAllText(file));
        input = new Mutator(seeds, _target.Dictionary, _target.MaxInputLength).Generate(_options.Seed, index);
        return Classify(input);
    }

    private IEnumerable<string> CorpusFiles()
    {
        if (_options.Corpus == null || !Directory.Exists(_options.Corpus)) return Array.Empty<string>();
        return Directory.GetFiles(_options.Corpus).Where(f => FuzzTargets.TargetOfFile(f) == _target.Name).OrderBy(f => f, StringComparer.Ordinal);
    }

    /// <summary>The result of one input.</summary>
    internal readonly record struct Outcome(bool Parsed, string Bucket, string Description, double Milliseconds);

    private Outcome Classify(string input)
    {
        _currentStart = Stopwatch.GetTimestamp();
        _current = input;
        bool parsed = false;
        string bucket = null, description = null;
        try
        {
            parsed = _target.Check(input);
        }
        catch (FuzzFailure e)
        {
            bucket = e.Kind + (e.InnerException != null ? ": " + Signature(e.InnerException) : "");
            description = e.Message;
        }
        catch (Exception e)
        {
            bucket = Signature(e);
            description = $"{e.GetType().Name}: {e.Message}";
        }
        double ms = Stopwatch.GetElapsedTime(_currentStart).TotalMilliseconds;
        _current = null;
        if (bucket == null && ms > _options.SlowMilliseconds)
        {
            bucket = "slow";
            description = $"took {ms:0} ms (limit {_options.SlowMilliseconds:0} ms)";
        }
        return new Outcome(parsed, bucket, description, ms);
    }

    // An exception's kind: its type and the first AvatarGo method on its stack.
    private static string Signature(Exception e)
    {
        var frames = new StackTrace(e).GetFrames();
        string where = frames.Select(f => f.GetMethod()).Where(m => m?.DeclaringType?.Namespace?.StartsWith("AvatarGo.Core", StringComparison.Ordinal) == true
                                                                  || m?.DeclaringType?.Namespace?.StartsWith("AvatarGo.Simulation", StringComparison.Ordinal) == true)
            .Select(m => (m.DeclaringType.DeclaringType ?? m.DeclaringType).Name + "." + m.Name).FirstOrDefault() ?? "?";
        return e.GetType().Name + " in " + where;
    }

    private void Record(FuzzReport report, Outcome outcome, string input, string origin, bool corpus)
    {
        report.Inputs++;
        if (_options.Trace) _log.WriteLine($"    {origin}: {input.Length} chars, {outcome.Milliseconds:0.0} ms, {(outcome.Parsed ? "parsed" : "refused")}");
        if (outcome.Parsed) report.Parsed++;
        if (outcome.Milliseconds > report.SlowestMilliseconds)
        {
            report.SlowestMilliseconds = outcome.Milliseconds;
            report.SlowestInput = origin;
        }
        if (outcome.Bucket == null) return;
        report.Failures++;
        _log.WriteLine($"  {_target.Name}: FAIL ({origin}, {input.Length:N0} chars): {outcome.Description}");
        if (_findings.TryGetValue(outcome.Bucket, out FuzzFinding known))
        {
            known.Count++;
            return;
        }
        var finding = new FuzzFinding(outcome.Bucket, outcome.Description, origin) { Count = 1 };
        _findings.Add(outcome.Bucket, finding);
        if (corpus) return; // already in the corpus: it fails again, which the report shows
        string example = input;
        if (_options.Minimize)
        {
            TimeSpan budget = TimeSpan.FromSeconds(outcome.Bucket == "slow" ? 60 : 20);
            example = Minimizer.Minimize(input, candidate => Classify(candidate).Bucket == outcome.Bucket, budget);
        }
        finding.Example = example;
        if (_options.Corpus == null) return;
        if (example.Length > _options.MaxSavedLength)
        {
            finding.SavedAs = $"(not saved: {example.Length:N0} characters after minimising)";
            return;
        }
        Directory.CreateDirectory(_options.Corpus);
        string hash = Convert.ToHexString(SHA256.HashData(Encoding.UTF8.GetBytes(example))).Substring(0, 12).ToLowerInvariant();
        string path = Path.Combine(_options.Corpus, $"{_target.Name}-{hash}{_target.Extension}");
        AtomicFileWriter.WriteAllText(path, example);
        finding.SavedAs = path;
    }

    private void Watch()
    {
        string input = _current;
        if (input == null || Stopwatch.GetElapsedTime(_currentStart).TotalSeconds < _options.HangSeconds) return;
        string path = Path.Combine(_options.Corpus ?? Path.GetTempPath(), $"{_target.Name}-hang-{Environment.ProcessId}{_target.Extension}");
        try
        {
            if (_options.Corpus != null) Directory.CreateDirectory(_options.Corpus);
            AtomicFileWriter.WriteAllText(path, input);
        }
        catch (IOException) { }
        _log.WriteLine($"  {_target.Name}: an input has run for {_options.HangSeconds} s; saved to {path}; stopping");
        _log.Flush();
        Environment.Exit(3);
    }
}
