using System;
using System.Text.Json;
using System.Text.Json.Serialization;

namespace AvatarGo.Cli;

/// <summary>
/// How the commands write their JSON reports: indented, and a number that is not finite (a statistic of no samples: a
/// session without some joint's truth) written as null, which JSON can hold, instead of failing the whole report with a
/// serializer message (found in review: `evaluate --json` on a session without knee truth exited 1 and wrote nothing).
/// </summary>
internal static class JsonReports
{
    public static readonly JsonSerializerOptions Options = new()
    {
        WriteIndented = true,
        Converters = { new FiniteOrNullDouble(), new FiniteOrNullFloat() },
    };

    public static string Serialize<T>(T value) => JsonSerializer.Serialize(value, Options);

    private sealed class FiniteOrNullDouble : JsonConverter<double>
    {
        public override bool HandleNull => false;
        public override double Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options) => reader.GetDouble();
        public override void Write(Utf8JsonWriter writer, double value, JsonSerializerOptions options)
        {
            if (double.IsFinite(value)) writer.WriteNumberValue(value);
            else writer.WriteNullValue();
        }
    }

    private sealed class FiniteOrNullFloat : JsonConverter<float>
    {
        public override float Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options) => reader.GetSingle();
        public override void Write(Utf8JsonWriter writer, float value, JsonSerializerOptions options)
        {
            if (float.IsFinite(value)) writer.WriteNumberValue(value);
            else writer.WriteNullValue();
        }
    }
}
