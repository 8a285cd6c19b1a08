#include <lacrima/editing/HighLevelCodes.h>

#include <array>

namespace lacrima::editing {
namespace {

constexpr std::array<HighLevelCode, 15> kVisemes{{
    {0, "none", "silence, neutral mouth"},
    {1, "PP", "p, b, m as in put, bed, mill"},
    {2, "FF", "f, v as in far, voice"},
    {3, "TH", "th as in think, that"},
    {4, "DD", "t, d as in tip, doll"},
    {5, "kk", "k, g as in call, gas"},
    {6, "CH", "ch, j, sh as in chair, join, she"},
    {7, "SS", "s, z as in sir, zeal"},
    {8, "nn", "n, l as in lot, not"},
    {9, "RR", "r as in red"},
    {10, "aa", "a as in car"},
    {11, "E", "e as in bed"},
    {12, "ih", "i as in tip"},
    {13, "oh", "o as in top"},
    {14, "ou", "u as in book"},
}};

constexpr std::array<HighLevelCode, 7> kExpressions{{
    {0, "neutral", "no expression"},
    {1, "joy", "brows relaxed, mouth open, corners pulled back"},
    {2, "sadness", "inner brows bent up, eyes partly closed, mouth relaxed"},
    {3, "anger", "inner brows down and together, eyes wide, lips pressed"},
    {4, "fear", "brows raised and drawn together, eyes tense and alert"},
    {5, "disgust", "upper lip raised and curled, often more on one side"},
    {6, "surprise", "brows raised, upper lids wide open, jaw dropped"},
}};

}  // namespace

std::span<const HighLevelCode> visemeCodes() { return kVisemes; }
std::span<const HighLevelCode> expressionCodes() { return kExpressions; }

}  // namespace lacrima::editing
