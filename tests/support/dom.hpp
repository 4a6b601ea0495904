#pragma once
// XML and HTML read back with libxml2: the grade's writers' files, and the DOM Chromium serialized.
#include <gtest/gtest.h>
#include <libxml/HTMLparser.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <libxml/xpath.h>

#include <memory>
#include <string>
#include <vector>

namespace frob::support {

struct DocFree {
  void operator()(xmlDoc* d) const { xmlFreeDoc(d); }
};
using Doc = std::unique_ptr<xmlDoc, DocFree>;

// A strict XML 1.0 parse: any well-formedness error (a bad character, a bad escape) gives null.
inline Doc parseXml(const std::string& text) {
  return Doc(
      xmlReadMemory(text.data(), static_cast<int>(text.size()), "report.xml", "UTF-8", XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING));
}

// An HTML parse, as lenient as a browser's (for Chromium's serialized DOM).
inline Doc parseHtml(const std::string& text) {
  return Doc(htmlReadMemory(text.data(), static_cast<int>(text.size()), "page.html", "UTF-8",
                            HTML_PARSE_NONET | HTML_PARSE_NOERROR | HTML_PARSE_NOWARNING | HTML_PARSE_NOBLANKS));
}

// The string values of the nodes `xpath` selects (attributes' values, elements' text).
inline std::vector<std::string> select(xmlDoc* doc, const std::string& xpath) {
  std::vector<std::string> values;
  xmlXPathContext* ctx = xmlXPathNewContext(doc);
  xmlXPathObject* found = xmlXPathEvalExpression(reinterpret_cast<const xmlChar*>(xpath.c_str()), ctx);
  if (found != nullptr && found->nodesetval != nullptr) {
    for (int i = 0; i < found->nodesetval->nodeNr; ++i) {
      xmlChar* text = xmlNodeGetContent(found->nodesetval->nodeTab[i]);
      values.emplace_back(text != nullptr ? reinterpret_cast<const char*>(text) : "");
      xmlFree(text);
    }
  }
  xmlXPathFreeObject(found);
  xmlXPathFreeContext(ctx);
  return values;
}

inline std::string one(xmlDoc* doc, const std::string& xpath) {
  const std::vector<std::string> v = select(doc, xpath);
  EXPECT_EQ(v.size(), 1u) << xpath;
  return v.empty() ? std::string("<none>") : v[0];
}

}  // namespace frob::support
